//! `uvt`: host tools for the uvt reference model.
#![forbid(unsafe_code)]

fn main() {
    println!("uvt {}", env!("CARGO_PKG_VERSION"));
}
