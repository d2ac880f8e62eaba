//! `diff.png` of `uvt render`: where the fixed-point image and the f64 reference's differ, and by
//! how much, with its legend drawn into the image like `heat.png`'s.
//!
//! **Colour.** A pixel's difference `d` is the largest of its R, G and B differences (0..=255
//! levels). `d = 0` is black; `d ≥ 1` runs along the ramp dark red → red → yellow → white at
//! position `x(d) = ½·ln d / ln 255 + ½·(d − 1)/254` ([`position`], [`diff_color`]): the log half
//! spreads the small differences (1 to 16 levels take 28% of the ramp), the linear half moves
//! every step by at least 1/508 of the ramp (≥ 1.5 levels of some channel, none falling), so
//! every larger difference is strictly brighter (a test holds this for every d).
//!
//! **Size.** The map and `heat.png` are enlarged by the smallest integer factor that makes
//! the image's larger side at least [`READABLE`] pixels ([`scale_for`]; nearest neighbour: one
//! scene pixel is a k×k block). `fixed.png` and `f64.png` stay at the viewport's size: they are
//! the model's pixels.

use super::heatmap::{text, text_width, MIN_W};

/// Height of the legend strip below the map, pixels.
pub const LEGEND_H: u32 = 44;
/// The larger side, in pixels, below which `diff.png` and `heat.png` are enlarged.
pub const READABLE: u32 = 256;

const CAPTION: &str = "DIFFERENCE IN RGB LEVELS";
/// The ramp's stops: dark red, red, yellow, white.
const STOPS: [[f64; 3]; 4] = [
    [0.25, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [1.0, 1.0, 1.0],
];

/// The ramp position of a difference of `d` ≥ 1 levels (module docs).
pub fn position(d: f64) -> f64 {
    0.5 * d.ln() / 255f64.ln() + 0.5 * (d - 1.0) / 254.0
}

/// The colour of a difference of `d` levels (module docs).
pub fn diff_color(d: u8) -> [u8; 3] {
    if d == 0 {
        return [0, 0, 0];
    }
    ramp(position(f64::from(d)))
}

/// The ramp at x in [0, 1].
fn ramp(x: f64) -> [u8; 3] {
    let f = x.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let i = (f.floor() as usize).min(STOPS.len() - 2);
    let a = f - i as f64;
    [0, 1, 2].map(|k| ((STOPS[i][k] * (1.0 - a) + STOPS[i + 1][k] * a) * 255.0).round() as u8)
}

/// The enlargement factor of a `w`×`h` image (module docs).
pub fn scale_for(w: u16, h: u16) -> u32 {
    let side = u32::from(w.max(h)).max(1);
    READABLE.div_ceil(side).max(1)
}

/// The largest R, G, B difference of each pixel of two images of the same size.
pub fn differences(a: &[[u8; 3]], b: &[[u8; 3]]) -> Vec<u8> {
    a.iter()
        .zip(b)
        .map(|(a, b)| (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0))
        .collect()
}

/// `diff.png`: the map of `diffs` (W×H, row-major, [`differences`]) enlarged by
/// [`scale_for`], with the legend strip below it (caption; a black swatch labelled 0; the ramp
/// from 1 to 255 levels labelled 1, 16 and 255 at their positions).
pub fn draw(w: u16, h: u16, diffs: &[u8]) -> image::RgbImage {
    let k = scale_for(w, h);
    let (mw, mh) = (u32::from(w) * k, u32::from(h) * k);
    let width = mw.max(MIN_W);
    let mut img = image::RgbImage::from_pixel(width, mh + LEGEND_H, image::Rgb([40, 40, 40]));
    for (i, &d) in diffs
        .iter()
        .enumerate()
        .take((u32::from(w) * u32::from(h)) as usize)
    {
        let (x, y) = (i as u32 % u32::from(w), i as u32 / u32::from(w));
        let c = image::Rgb(diff_color(d));
        for dy in 0..k {
            for dx in 0..k {
                img.put_pixel(x * k + dx, y * k + dy, c);
            }
        }
    }
    let white = [255, 255, 255];
    let y = mh + 4;
    text(&mut img, 4, y, CAPTION, white);
    // The black swatch of "equal", then the ramp.
    for x in 4..14 {
        for dy in 0..10 {
            img.put_pixel(x, y + 14 + dy, image::Rgb([0, 0, 0]));
        }
    }
    text(&mut img, 6, y + 27, "0", white);
    let (x0, x1) = (20, width - 4);
    let at = |d: f64| x0 + ((x1 - 1 - x0) as f64 * position(d)).round() as u32;
    for x in x0..x1 {
        let c = ramp((x - x0) as f64 / (x1 - 1 - x0) as f64);
        for dy in 0..10 {
            img.put_pixel(x, y + 14 + dy, image::Rgb(c));
        }
    }
    for (d, s, align) in [(1.0, "1", 0), (16.0, "16", 1), (255.0, "255", 2)] {
        let (x, tw) = (at(d), text_width(s));
        let left = match align {
            0 => x,
            1 => x.saturating_sub(tw / 2),
            _ => x.saturating_sub(tw),
        };
        text(&mut img, left, y + 27, s, white);
    }
    img
}

#[cfg(test)]
mod tests {
    use super::*;

    fn luma(c: [u8; 3]) -> f64 {
        0.2126 * f64::from(c[0]) + 0.7152 * f64::from(c[1]) + 0.0722 * f64::from(c[2])
    }

    /// Every larger difference is strictly brighter, 0 is black, 255 white.
    #[test]
    fn the_scale_is_monotone() {
        assert_eq!(diff_color(0), [0, 0, 0]);
        assert_eq!(diff_color(255), [255, 255, 255]);
        for d in 1..=255u8 {
            let (a, b) = (diff_color(d - 1), diff_color(d));
            assert!(
                luma(b) > luma(a) && (0..3).all(|k| b[k] >= a[k]),
                "d = {d} ({d:#04x}): {b:?} not brighter than {a:?} (d − 1)"
            );
        }
        // Distinct colours for the small differences the old scale merged (1..=13 levels).
        let small: std::collections::BTreeSet<[u8; 3]> = (1..=13).map(diff_color).collect();
        assert_eq!(small.len(), 13);
    }

    #[test]
    fn small_images_are_enlarged() {
        assert_eq!(scale_for(64, 48), 4);
        assert_eq!(scale_for(320, 180), 1);
        assert_eq!(scale_for(255, 10), 2);
        assert_eq!(scale_for(1, 1), 256);
        // 2×1 pixels: ×128, 256×128 and the legend.
        let img = draw(2, 1, &[0, 200]);
        assert_eq!(img.width(), 256);
        assert_eq!(img.height(), 128 + LEGEND_H);
        assert_eq!(img.get_pixel(127, 127).0, [0, 0, 0]);
        assert_eq!(img.get_pixel(128, 0).0, diff_color(200));
        assert_eq!(img.get_pixel(255, 127).0, diff_color(200));
    }
}
