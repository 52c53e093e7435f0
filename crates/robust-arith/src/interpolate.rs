//! The second stage of the intersection calculation (section 7.1.1): the
//! intersection point of two segments, exactly as Table 7.2.

use crate::Point2;

/// The intersection point of segment A, `(x_l, y_al) -> (x_r, y_ar)`, and
/// segment B, `(x_l, y_bl) -> (x_r, y_br)`, computed exactly as the code of
/// Table 7.2.
///
/// Precondition (not checked): `y_al <= y_bl` and `y_br <= y_ar` with one of
/// them strict, so `dy_l - dy_r > 0` and there is no division by zero
/// (eq. 4.4). In the pyramid the "left" pair is the one where B shadows A
/// (`Delta_+ = y_bl - y_al >= 0`, eq. 4.5) and the "right" pair the one where
/// A shadows B (`Delta_- = y_br - y_ar < 0`, eq. 4.6); `x_l` need not be
/// smaller than `x_r`.
///
/// The point is interpolated from the end it is closer to (exact when the
/// segments meet at an end) and its y from the segment of smaller absolute
/// slope (exact when one segment is horizontal). It lies in the intersection
/// of the two bounding boxes (eq. 8.18-8.19) and within `sqrt(153) u L` of
/// both segments (eq. 8.17).
#[inline]
pub fn interpolate(x_l: f64, y_al: f64, y_bl: f64, x_r: f64, y_ar: f64, y_br: f64) -> Point2 {
    // Table 7.2, statement by statement.
    let dy_l = y_bl - y_al;
    let dy_r = y_br - y_ar;
    let dy_l_less = dy_l < -dy_r;
    let dx = x_r - x_l;
    let dy_a = y_ar - y_al;
    let dy_b = y_br - y_bl;
    let dy_a_less = dy_a.abs() < dy_b.abs();
    let lambda = (if dy_l_less { dy_l } else { dy_r }) / (dy_l - dy_r);
    let x_i = (if dy_l_less { x_l } else { x_r }) + lambda * dx;
    let y_i = (if dy_l_less {
        if dy_a_less {
            y_al
        } else {
            y_bl
        }
    } else if dy_a_less {
        y_ar
    } else {
        y_br
    }) + lambda * (if dy_a_less { dy_a } else { dy_b });
    [x_i, y_i]
}
