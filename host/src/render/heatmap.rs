//! The heat map of `uvt render` (sample tests per pixel) with its legend drawn into the image: a
//! caption, the colour scale and its numbers (0, half and the maximum), in a tiny built-in 3×5
//! bitmap font drawn at twice the size (no font files needed).

/// Height of the legend strip below the map, pixels.
pub const LEGEND_H: u32 = 44;
/// Smallest image width, so the caption fits on small viewports.
pub const MIN_W: u32 = 232;

const CAPTION: &str = "SAMPLE TESTS PER PIXEL";
const SCALE: u32 = 2;

/// Black → blue → red → yellow → white for x in [0, 1].
pub fn heat_color(x: f64) -> [u8; 3] {
    let stops = [
        [0.0, 0.0, 0.0],
        [0.1, 0.2, 0.9],
        [0.9, 0.1, 0.1],
        [1.0, 0.9, 0.1],
        [1.0, 1.0, 1.0],
    ];
    let f = x.clamp(0.0, 1.0) * (stops.len() - 1) as f64;
    let i = (f.floor() as usize).min(stops.len() - 2);
    let a = f - i as f64;
    [0, 1, 2].map(|k| ((stops[i][k] * (1.0 - a) + stops[i + 1][k] * a) * 255.0) as u8)
}

/// Rows of a 3×5 glyph, bit 2 = left column; unknown characters are blank.
fn glyph(c: char) -> [u8; 5] {
    match c {
        '0' => [7, 5, 5, 5, 7],
        '1' => [2, 6, 2, 2, 7],
        '2' => [7, 1, 7, 4, 7],
        '3' => [7, 1, 3, 1, 7],
        '4' => [5, 5, 7, 1, 1],
        '5' => [7, 4, 7, 1, 7],
        '6' => [7, 4, 7, 5, 7],
        '7' => [7, 1, 1, 2, 2],
        '8' => [7, 5, 7, 5, 7],
        '9' => [7, 5, 7, 1, 7],
        '.' => [0, 0, 0, 0, 2],
        'A' => [2, 5, 7, 5, 5],
        'B' => [6, 5, 6, 5, 6],
        'C' => [7, 4, 4, 4, 7],
        'D' => [6, 5, 5, 5, 6],
        'E' => [7, 4, 6, 4, 7],
        'F' => [7, 4, 6, 4, 4],
        'G' => [7, 4, 5, 5, 7],
        'I' => [7, 2, 2, 2, 7],
        'L' => [4, 4, 4, 4, 7],
        'M' => [5, 7, 7, 5, 5],
        'N' => [6, 5, 5, 5, 5],
        'P' => [6, 5, 6, 4, 4],
        'R' => [6, 5, 6, 5, 5],
        'S' => [7, 4, 7, 1, 7],
        'T' => [7, 2, 2, 2, 2],
        'V' => [5, 5, 5, 5, 2],
        'X' => [5, 5, 2, 5, 5],
        _ => [0; 5],
    }
}

/// Width in pixels of `s` drawn by [`text`].
pub fn text_width(s: &str) -> u32 {
    s.chars().count() as u32 * 4 * SCALE
}

/// Draw `s` with its top-left corner at (x, y), clipped to the image.
pub fn text(img: &mut image::RgbImage, x: u32, y: u32, s: &str, color: [u8; 3]) {
    for (i, c) in s.chars().enumerate() {
        let g = glyph(c);
        for (row, bits) in g.iter().enumerate() {
            for col in 0..3u32 {
                if bits & (4 >> col) == 0 {
                    continue;
                }
                for dy in 0..SCALE {
                    for dx in 0..SCALE {
                        let px = x + (i as u32 * 4 + col) * SCALE + dx;
                        let py = y + row as u32 * SCALE + dy;
                        if px < img.width() && py < img.height() {
                            img.put_pixel(px, py, image::Rgb(color));
                        }
                    }
                }
            }
        }
    }
}

/// The heat map of `counts` (W×H, row-major), each pixel a `k`×`k` block (`k` ≥ 1: the
/// enlargement of small images, `super::diff::scale_for`), with the legend strip below it. The
/// colour of a pixel is `heat_color(n / max)`; the scale is labelled 0, max/2 and max tests.
pub fn draw(w: u16, h: u16, counts: &[u32], k: u32) -> image::RgbImage {
    let k = k.max(1);
    let (w, h) = (w as u32, h as u32);
    let max = counts.iter().copied().max().unwrap_or(0).max(1);
    let width = (w * k).max(MIN_W);
    let mut img = image::RgbImage::from_pixel(width, h * k + LEGEND_H, image::Rgb([40, 40, 40]));
    for (i, &n) in counts.iter().enumerate().take((w * h) as usize) {
        let c = image::Rgb(heat_color(n as f64 / max as f64));
        let (x, y) = (i as u32 % w, i as u32 / w);
        for dy in 0..k {
            for dx in 0..k {
                img.put_pixel(x * k + dx, y * k + dy, c);
            }
        }
    }
    let white = [255, 255, 255];
    let y = h * k + 4;
    text(&mut img, 4, y, CAPTION, white);
    let (x0, x1) = (4, width - 4);
    for x in x0..x1 {
        let c = heat_color((x - x0) as f64 / (x1 - 1 - x0) as f64);
        for dy in 0..10 {
            img.put_pixel(x, y + 14 + dy, image::Rgb(c));
        }
    }
    let labels = [
        (x0, "0".to_string()),
        ((x0 + x1) / 2, format!("{:.1}", max as f64 / 2.0)),
        (x1, max.to_string()),
    ];
    for (i, (x, s)) in labels.iter().enumerate() {
        let tw = text_width(s);
        let left = match i {
            0 => *x,
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

    #[test]
    fn legend_is_drawn() {
        let counts: Vec<u32> = (0..32 * 8).map(|i| i % 17).collect();
        let img = draw(32, 8, &counts, 1);
        assert_eq!((img.width(), img.height()), (MIN_W, 8 + LEGEND_H));
        // The map's brightest pixel (16 tests) is white, the scale's ends are black and white.
        assert_eq!(img.get_pixel(16, 0).0, [255, 255, 255]);
        assert_eq!(img.get_pixel(4, 8 + 4 + 14).0, [0, 0, 0]);
        assert_eq!(img.get_pixel(MIN_W - 5, 8 + 4 + 14).0, [255, 255, 255]);
        // Caption and labels put white pixels into the strip's text rows.
        let white_in = |y0: u32, y1: u32| {
            (y0..y1)
                .flat_map(|y| (0..img.width()).map(move |x| (x, y)))
                .filter(|&(x, y)| img.get_pixel(x, y).0 == [255, 255, 255])
                .count()
        };
        assert!(white_in(12, 22) > 100, "caption");
        assert!(white_in(39, 49) > 20, "labels");
    }
}
