//! Lines on the standard error — progress and warnings — written by [`line`], which every
//! command uses instead of `eprintln!`: a closed standard error (`uvt render 2>&1 | head -1`)
//! loses the line silently instead of panicking (exit status 101), and the command goes on (it
//! ends quietly at its next write to a closed standard output).

use std::io::Write;

/// Write `text` and a newline to the standard error; a failed write (a closed pipe) is ignored.
pub fn line(text: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{text}");
}
