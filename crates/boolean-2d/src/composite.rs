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
    if !edge.is_balanced() {
        return None;
    }
    match edge.starts.len() {
        0 => return Some(()),
        1 => {
            out.push((edge.starts[0].0, edge.ends[0].0));
            return Some(());
        }
        _ => {}
    }
    // eq. 4.14
    let mut v = [0.0f64; 2];
    for &(_, p) in &edge.ends {
        v[0] += p[0];
        v[1] += p[1];
    }
    for &(_, p) in &edge.starts {
        v[0] -= p[0];
        v[1] -= p[1];
    }
    let key = |p: &[f64; 2]| p[0] * v[0] + p[1] * v[1];
    // eq. 4.15-4.16: a stable sort by the projection onto v (two items,
    // the common case: swapped exactly when the second is less).
    for list in [&mut edge.starts, &mut edge.ends] {
        if let [first, second] = list.as_mut_slice() {
            if key(&second.1).total_cmp(&key(&first.1)).is_lt() {
                std::mem::swap(first, second);
            }
        } else {
            list.sort_by(|a, b| key(&a.1).total_cmp(&key(&b.1)));
        }
    }
    out.extend(
        edge.starts
            .iter()
            .zip(edge.ends.iter())
            .map(|(s, e)| (s.0, e.0)),
    );
    Some(())
}
