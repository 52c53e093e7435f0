//! SVG writing of 2D polygon sets: one `<path>` holding every ring as a
//! closed subpath, filled with `fill-rule="nonzero"`.
//!
//! Rings are laid out by role ([`crate::layout_polygons`]): outer rings
//! counter-clockwise, holes clockwise, so the winding number of the path is
//! the set's winding number (1 inside, 0 in holes and outside) and the
//! non-zero rule fills exactly the set. SVG's y axis points down, so every
//! y is negated (the picture is not mirrored; the rings' directions flip,
//! which the non-zero rule does not see). The `viewBox` is the bounding box
//! with a margin of 5% of its larger side (1 unit for a single point).
//! Coordinates are the shortest decimals that read back to the same `f64`.

use super::rings::layout_polygons;
use super::text::push_f64;
use crate::{RingOrientation, UmbraError};
use topology::PolygonSet2;

/// The SVG text of a polygon set and the number of orphan holes of the
/// by-role layout (see [`crate::PolygonLayout::orphan_holes`]; an
/// inside-out part is drawn filled).
///
/// ```
/// use umbra::{polygon_set_to_svg, PolygonSet2};
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0]]);
/// let (svg, orphans) = polygon_set_to_svg(&s).unwrap();
/// assert_eq!(orphans, 0);
/// assert!(svg.contains(r#"d="M0 -0L2 -0L2 -1Z""#));
/// assert!(svg.contains(r#"viewBox="-0.1 -1.1 2.2 1.2""#));
/// ```
pub fn polygon_set_to_svg(set: &PolygonSet2) -> Result<(String, usize), UmbraError> {
    let layout = layout_polygons(set, RingOrientation::ByRole, "<output>")?;
    let (lo, hi) = match set.bounding_box() {
        Some([lo, hi]) => (lo, hi),
        None => ([0.0, 0.0], [0.0, 0.0]),
    };
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    let side = w.max(h);
    let margin = if side > 0.0 { side * 0.05 } else { 1.0 };
    let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    s.push_str("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
    for (i, v) in [
        lo[0] - margin,
        -hi[1] - margin,
        w + 2.0 * margin,
        h + 2.0 * margin,
    ]
    .into_iter()
    .enumerate()
    {
        if i > 0 {
            s.push(' ');
        }
        push_f64(&mut s, v);
    }
    s.push_str(
        "\">\n  <path fill=\"#4a7ab5\" fill-rule=\"nonzero\" stroke=\"#1d3557\" stroke-width=\"",
    );
    push_f64(&mut s, margin / 10.0);
    s.push_str("\" stroke-linejoin=\"round\" d=\"");
    for ring in layout.polygons.iter().flatten() {
        for (i, p) in ring.iter().enumerate() {
            s.push(if i == 0 { 'M' } else { 'L' });
            push_f64(&mut s, p[0]);
            s.push(' ');
            push_f64(&mut s, -p[1]);
        }
        if !ring.is_empty() {
            s.push('Z');
        }
    }
    s.push_str("\"/>\n</svg>\n");
    Ok((s, layout.orphan_holes))
}
