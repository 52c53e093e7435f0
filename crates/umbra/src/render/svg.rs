//! A small SVG writer: numbers and fixed colours only, nothing taken from
//! the user's data but coordinates.

use std::fmt::Write;

/// A colour as `#rrggbb`.
fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// A coordinate with two decimals (finite by construction; anything else
/// is written as 0 so the document stays well-formed).
pub(crate) fn num(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.2}")
    } else {
        "0".to_string()
    }
}

/// An SVG document being written.
pub(crate) struct Svg {
    out: String,
}

impl Svg {
    /// A document of `width x height` user units on a `background`.
    pub(crate) fn new(width: u32, height: u32, background: [u8; 3]) -> Svg {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\">\n<rect x=\"0\" y=\"0\" width=\"{width}\" height=\"{height}\" fill=\"{}\"/>",
            hex(background)
        );
        Svg { out }
    }

    /// A path (`d` built of [`path_data`]), filled even-odd, stroked in
    /// `stroke` when given.
    pub(crate) fn path(&mut self, d: &str, fill: [u8; 3], stroke: Option<([u8; 3], f64)>) {
        let _ = write!(
            self.out,
            "<path d=\"{d}\" fill=\"{}\" fill-rule=\"evenodd\"",
            hex(fill)
        );
        match stroke {
            Some((c, w)) => {
                let _ = writeln!(
                    self.out,
                    " stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\"/>",
                    hex(c),
                    num(w)
                );
            }
            None => self.out.push_str("/>\n"),
        }
    }

    /// A filled rectangle (crisp edges).
    pub(crate) fn rect(&mut self, x: u32, y: u32, w: u32, h: u32, fill: [u8; 3]) {
        let _ = writeln!(
            self.out,
            "<rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" fill=\"{}\" shape-rendering=\"crispEdges\"/>",
            hex(fill)
        );
    }

    /// A segment with round caps.
    pub(crate) fn line(&mut self, a: [f64; 2], b: [f64; 2], colour: [u8; 3], width: f64) {
        let _ = writeln!(
            self.out,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\"/>",
            num(a[0]),
            num(a[1]),
            num(b[0]),
            num(b[1]),
            hex(colour),
            num(width)
        );
    }

    /// A filled disc.
    pub(crate) fn circle(&mut self, c: [f64; 2], r: f64, colour: [u8; 3]) {
        let _ = writeln!(
            self.out,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/>",
            num(c[0]),
            num(c[1]),
            num(r),
            hex(colour)
        );
    }

    /// A filled polygon.
    pub(crate) fn polygon(&mut self, points: &[[f64; 2]], fill: [u8; 3]) {
        let pts: Vec<String> = points
            .iter()
            .map(|p| format!("{},{}", num(p[0]), num(p[1])))
            .collect();
        let _ = writeln!(
            self.out,
            "<polygon points=\"{}\" fill=\"{}\"/>",
            pts.join(" "),
            hex(fill)
        );
    }

    /// The finished document.
    pub(crate) fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// Path data of closed loops of points.
pub(crate) fn path_data(loops: &[Vec<[f64; 2]>]) -> String {
    let mut d = String::new();
    for l in loops.iter().filter(|l| !l.is_empty()) {
        for (i, p) in l.iter().enumerate() {
            let _ = write!(
                d,
                "{}{} {} ",
                if i == 0 { "M" } else { "L" },
                num(p[0]),
                num(p[1])
            );
        }
        d.push('Z');
    }
    d
}
