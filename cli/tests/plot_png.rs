//! PNG output of `gam plot` and `gam figures`: the file decodes as a PNG of the documented
//! size, the series are drawn in their colours in the right panels, the title's text pixels
//! (DejaVu Sans, bundled; no system font) sit in the title's box, `--format` overrides
//! the extension, and an unwritable path is one `error:` line with exit status 2.

use crate::common;

use common::{TempFile, fails, ok};

/// A decoded RGB image.
struct Image {
    width: usize,
    height: usize,
    rgb: Vec<u8>,
}

impl Image {
    fn at(&self, x: usize, y: usize) -> [u8; 3] {
        let i = 3 * (y * self.width + x);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// The pixels `(x, y)` of colour `c` inside `xs × ys`.
    fn find(&self, c: [u8; 3], xs: std::ops::Range<usize>, ys: std::ops::Range<usize>) -> Vec<(usize, usize)> {
        ys.flat_map(|y| xs.clone().map(move |x| (x, y))).filter(|(x, y)| self.at(*x, *y) == c).collect()
    }
}

/// Decodes `bytes` with the `png` crate, checking the signature and the IHDR chunk by hand first.
fn decode(bytes: &[u8]) -> Image {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "the PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR", "IHDR is the first chunk");
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]) as usize;
    let (w, h) = (be(16), be(20));
    assert_eq!((bytes[24], bytes[25]), (8, 2), "8-bit RGB");
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().expect("a valid PNG");
    let mut rgb = vec![0; reader.output_buffer_size().expect("a buffer size")];
    let info = reader.next_frame(&mut rgb).expect("the image data decodes");
    assert_eq!((info.width as usize, info.height as usize), (w, h));
    assert_eq!(info.color_type, png::ColorType::Rgb);
    rgb.truncate(info.buffer_size());
    Image { width: w, height: h, rgb }
}

const SPEC: &str = r#"{"method": "ccm-additive",
  "poses": [{"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0},
            {"position": [1, 1, 0], "axis": [0, 0, 1], "angle": 1},
            {"position": [2, 0, 1], "axis": [1, 0, 0], "angle": 0.5}]}"#;

/// The first series colour (its speed, dashed angular speed and path).
const BLUE: [u8; 3] = [0, 136, 255];
/// The legend band's background.
const LEGEND: [u8; 3] = [250, 250, 250];

/// The `width` and `height` of an SVG file's root element.
fn svg_size(path: &str) -> (usize, usize) {
    let svg = std::fs::read_to_string(path).expect("the SVG was written");
    let attr = |name: &str| {
        let at = svg.find(&format!(" {name}=\"")).expect(name) + name.len() + 3;
        svg[at..at + svg[at..].find('"').unwrap()].parse().expect("a size")
    };
    (attr("width"), attr("height"))
}
/// The frames' e1 axis.
const AXIS_RED: [u8; 3] = [220, 0, 0];

#[test]
fn a_png_plot_has_its_size_series_colours_and_title_text() {
    let spec = TempFile::new("png-spec.json", SPEC);
    let out = TempFile::empty("plot.png");
    let line = ok(&["plot", spec.path(), "--out", out.path(), "--frames", "3"]);
    let title = "ccm-additive motion of 2 segments of degree 3, body point [0, 0, 0]";
    assert_eq!(line, format!("wrote {}: {title} (201 samples)", out.path()));
    let img = decode(&std::fs::read(out.path()).expect("the PNG was written"));
    // The SVG of the same figure has the same size: 1200 wide, the panels 560 high and the
    // legend band under them.
    let svg = TempFile::empty("plot-png-twin.svg");
    ok(&["plot", spec.path(), "--out", svg.path(), "--frames", "3"]);
    assert_eq!((img.width, img.height), svg_size(svg.path()));
    assert!(img.width == 1200 && img.height > 580, "{} x {}", img.width, img.height);
    // The background is white; the speed panel is the left half, the path panel the right,
    // the legend band below 560.
    assert_eq!(img.at(1, 1), [255; 3]);
    assert_eq!(img.at(1198, 558), [255; 3]);
    let left_blue = img.find(BLUE, 80..590, 60..520).len();
    let right_blue = img.find(BLUE, 680..1190, 60..520).len();
    assert!(left_blue > 300 && right_blue > 300, "speed {left_blue}, path {right_blue} blue pixels");
    assert!(img.find(LEGEND, 0..1200, 560..img.height).len() > 10_000, "the legend band");
    assert!(img.find(BLUE, 0..1200, 560..img.height).len() > 20, "the legend's swatches");
    assert!(img.find(AXIS_RED, 600..1200, 40..560).len() > 20, "the frames' e1 axes in the path panel");
    assert!(img.find(AXIS_RED, 0..600, 0..560).is_empty());
    // The title: dark text pixels in the top band, all inside the box plotters lays it out in
    // (0.7 em per character, em = 22 / 1.24²), centred on the image, and as wide as a
    // proportional font's text: more than 0.6 of that box (DejaVu Sans' advances average
    // about 0.55 of the drawn em, 1.24 times plotters' em).
    let em = 22.0 / 1.24 / 1.24;
    let half = 0.35 * em * title.len() as f64;
    let band: Vec<(usize, usize)> = (0..28).flat_map(|y| (0..1200).map(move |x| (x, y))).collect();
    let dark: Vec<&(usize, usize)> = band.iter().filter(|(x, y)| img.at(*x, *y).iter().all(|c| *c < 96)).collect();
    assert!(dark.len() > 500, "{} title pixels", dark.len());
    for (x, _) in &dark {
        assert!((*x as f64 - 600.0).abs() <= half + 2.0, "a title pixel at x = {x}, half width {half}");
    }
    let (lo, hi) = (dark.iter().map(|p| p.0).min().unwrap(), dark.iter().map(|p| p.0).max().unwrap());
    assert!(((lo + hi) as f64 / 2.0 - 600.0).abs() <= 2.0, "the title spans {lo}..{hi}");
    assert!((hi - lo) as f64 > 0.6 * 2.0 * half, "the title spans {lo}..{hi}, the box {half} each side");
}

#[test]
fn the_format_flag_overrides_the_extension_and_the_pixels_repeat() {
    let spec = TempFile::new("png-spec2.json", SPEC);
    let a = TempFile::empty("forced.svg");
    ok(&["plot", spec.path(), "--out", a.path(), "--format", "png", "--view", "3d", "--frames", "2", "--body", "cube"]);
    let png = std::fs::read(a.path()).expect("written");
    let img = decode(&png);
    assert_eq!(img.width, 1200);
    assert!(img.find([90, 90, 90], 600..1200, 40..560).len() > 50, "the cubes' grey edges");
    // The same figure again is the same file, byte for byte (nothing depends on the machine).
    let b = TempFile::empty("again.png");
    ok(&["plot", spec.path(), "--out", b.path(), "--view", "3d", "--frames", "2", "--body", "cube"]);
    assert_eq!(std::fs::read(b.path()).expect("written"), png);
    // And `--format svg` writes SVG whatever the name.
    let c = TempFile::empty("forced.png");
    ok(&["plot", spec.path(), "--out", c.path(), "--format", "svg"]);
    let text = std::fs::read_to_string(c.path()).expect("SVG text");
    assert!(text.starts_with("<svg"), "{}", &text[..40]);
}

#[test]
fn an_unwritable_png_is_one_error_line() {
    let spec = TempFile::new("png-spec3.json", SPEC);
    let line = fails(&["plot", spec.path(), "--out", "/nonexistent-dir/fig.png"], 2);
    assert!(line.contains("cannot write `/nonexistent-dir/fig.png`"), "{line}");
    let line = fails(&["plot", spec.path(), "--out", "x.png", "--format", "jpeg"], 2);
    assert!(line.contains("jpeg"), "{line}");
    let line = fails(&["figures", "--out", "/nonexistent-dir/gam-figures", "--format", "png"], 2);
    assert!(line.contains("cannot write `/nonexistent-dir/gam-figures/fig3.png`"), "{line}");
}

#[test]
fn figures_in_png_are_the_svg_gallery_as_images() {
    let dir = std::env::temp_dir().join(format!("gam-cli-test-{}-png-figures", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp dir");
    let d = dir.to_str().expect("utf-8");
    let lines = ok(&["figures", "--out", d, "--format", "png"]);
    let svgs = dir.join("svg");
    std::fs::create_dir_all(&svgs).expect("a temp dir");
    ok(&["figures", "--out", svgs.to_str().expect("utf-8")]);
    let files: Vec<&str> = lines.lines().map(|l| l.split(": ").next().unwrap().trim_start_matches("wrote ")).collect();
    assert_eq!(files.len(), 21, "{lines}");
    for f in &files {
        assert!(f.ends_with(".png"), "{f}");
        let img = decode(&std::fs::read(f).expect("written"));
        let name = std::path::Path::new(f).file_stem().and_then(|s| s.to_str()).expect("a name");
        let size = svg_size(svgs.join(format!("{name}.svg")).to_str().expect("utf-8"));
        assert_eq!((img.width, img.height), size, "{f}");
        let blue = img.find(BLUE, 0..img.width, 40..img.height).len();
        assert!(blue > 300, "{f}: {blue} pixels of the first series' colour");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
