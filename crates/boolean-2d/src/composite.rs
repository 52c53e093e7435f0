//! Composite edges (level 3 in 2D, level 4 in 3D; section 4.6): start- and
//! end-vertices from net end-vertex counts, paired by eq. 4.14-4.16.

/// A composite edge under construction: every vertex assigned a net
/// end-vertex count `n` (section 4.6) is entered `n` times as an end-vertex
/// (`n > 0`) or `-n` times as a start-vertex (`n < 0`).
#[derive(Clone, Debug, Default)]
pub struct CompositeEdge {
    /// Start-vertices: `(vertex id, position)`.
    pub starts: Vec<(u32, [f64; 2])>,
    /// End-vertices: `(vertex id, position)`.
    pub ends: Vec<(u32, [f64; 2])>,
}

impl CompositeEdge {
    /// Assigns vertex `id` at `pos` a net end-vertex count `n`.
    pub fn assign(&mut self, id: u32, pos: [f64; 2], n: i32) {
        let list = if n > 0 {
            &mut self.ends
        } else {
            &mut self.starts
        };
        for _ in 0..n.unsigned_abs() {
            list.push((id, pos));
        }
    }

    /// Theorem 2: the number of start-vertices equals the number of
    /// end-vertices.
    pub fn is_balanced(&self) -> bool {
        self.starts.len() == self.ends.len()
    }

    /// Clears the edge for reuse (keeping its allocations).
    pub fn clear(&mut self) {
        self.starts.clear();
        self.ends.clear();
    }
}

/// Pairs start- and end-vertices into single-segment edges `(start, end)`:
/// both lists are ordered along `v = sum x_e - sum x_s` (eq. 4.14) so that
/// `(x_{i+1} - x_i) . v >= 0` (eq. 4.15-4.16), and paired in order. Any
/// pairing keeps the topology; this one keeps the geometry when the input
/// is valid. Ties keep the order of assignment, so the result is
/// deterministic.
///
/// Returns `None` when the counts differ (which Theorem 2 rules out).
pub fn pair_composite_edge(edge: &mut CompositeEdge, out: &mut Vec<(u32, u32)>) -> Option<()> {
    pair_along(&mut edge.starts, &mut edge.ends, |v| v.1, |v| v.0, out)
}

/// [`pair_composite_edge`] on start- and end-vertices of any form: `pos`
/// gives a vertex's position (read only when there are two or more pairs)
/// and `id` its id.
pub(crate) fn pair_along<T>(
    starts: &mut [T],
    ends: &mut [T],
    pos: impl Fn(&T) -> [f64; 2],
    id: impl Fn(&T) -> u32,
    out: &mut Vec<(u32, u32)>,
) -> Option<()> {
    if starts.len() != ends.len() {
        return None;
    }
    match starts.len() {
        0 => return Some(()),
        1 => {
            out.push((id(&starts[0]), id(&ends[0])));
            return Some(());
        }
        _ => {}
    }
    // eq. 4.14
    let mut v = [0.0f64; 2];
    for e in ends.iter() {
        let p = pos(e);
        v[0] += p[0];
        v[1] += p[1];
    }
    for s in starts.iter() {
        let p = pos(s);
        v[0] -= p[0];
        v[1] -= p[1];
    }
    let key = |t: &T| {
        let p = pos(t);
        p[0] * v[0] + p[1] * v[1]
    };
    // eq. 4.15-4.16: a stable sort by the projection onto v (two items,
    // the common case: swapped exactly when the second is less).
    for list in [&mut *starts, &mut *ends] {
        if let [first, second] = list {
            if key(second).total_cmp(&key(first)).is_lt() {
                std::mem::swap(first, second);
            }
        } else {
            list.sort_by(|a, b| key(a).total_cmp(&key(b)));
        }
    }
    out.extend(starts.iter().zip(ends.iter()).map(|(s, e)| (id(s), id(e))));
    Some(())
}
