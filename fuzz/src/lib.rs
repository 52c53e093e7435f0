//! Shared `Arbitrary` inputs for the fuzz targets. Each input's `Debug`
//! prints a ready-to-paste Rust test case, so a minimized crash becomes a
//! regression test by copying the fuzzer's output.

use arbitrary::Arbitrary;
use std::fmt;
use test_support::shapes::{CUBE_FACES, OCTA_FACES, TETRA_FACES};
use topology::{Facet, PolygonMesh, PolygonSet2, TriangleMesh};

/// A coordinate: mostly small integers (exact ties everywhere), sometimes
/// arbitrary bit patterns (NaN, infinities, huge and subnormal values).
#[derive(Clone, Copy, Arbitrary)]
pub enum Coord {
    /// A small integer-grid value.
    Grid(i8),
    /// A value in [-1, 1] with a 16-bit mantissa.
    Unit(i16),
    /// Any f64 bit pattern.
    Bits(u64),
}

impl Coord {
    /// The f64 value.
    pub fn value(self) -> f64 {
        match self {
            Coord::Grid(i) => f64::from(i % 8),
            Coord::Unit(i) => f64::from(i) / 32768.0,
            Coord::Bits(b) => f64::from_bits(b),
        }
    }
}

/// A polygon set given as closed loops of points; each loop may be
/// reversed and repeated (multiplicity).
#[derive(Clone, Arbitrary)]
pub struct Loops {
    /// The loops: points, and a multiplicity in -2..=2.
    pub loops: Vec<(Vec<(Coord, Coord)>, i8)>,
}

impl Loops {
    /// The polygon set (always topologically valid: every loop is closed).
    pub fn to_set(&self) -> PolygonSet2 {
        let mut s = PolygonSet2::new();
        for (points, mult) in self.loops.iter().take(8) {
            let pts: Vec<[f64; 2]> = points
                .iter()
                .take(32)
                .map(|(x, y)| [x.value(), y.value()])
                .collect();
            if pts.is_empty() {
                continue;
            }
            let first = s.vertex_count() as u32;
            for &p in &pts {
                s.add_vertex(p);
            }
            let n = pts.len() as u32;
            let m = i32::from(*mult % 3);
            for i in 0..n {
                s.add_edge_mult(first + i, first + (i + 1) % n, m);
            }
        }
        s
    }
}

impl fmt::Debug for Loops {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.to_set();
        writeln!(f, "PolygonSet2::from_parts(")?;
        writeln!(f, "    vec![")?;
        for p in s.vertices() {
            writeln!(
                f,
                "        [f64::from_bits({:#x}), f64::from_bits({:#x})],",
                p[0].to_bits(),
                p[1].to_bits()
            )?;
        }
        writeln!(f, "    ],")?;
        writeln!(f, "    vec![")?;
        for e in s.edges() {
            writeln!(
                f,
                "        Edge2 {{ start: {}, end: {}, mult: {} }},",
                e.start, e.end, e.mult
            )?;
        }
        writeln!(f, "    ],")?;
        write!(f, ")")
    }
}

/// Two operands and an operation.
#[derive(Clone, Arbitrary, Debug)]
pub struct BooleanInput {
    /// Operand A.
    pub a: Loops,
    /// Operand B.
    pub b: Loops,
    /// 0 union, 1 intersection, otherwise difference.
    pub op: u8,
}

/// A closed solid template: its facets as vertex loops over `vertices`
/// local vertices, outward for the natural coordinates.
#[derive(Clone, Copy, Arbitrary, Debug)]
pub enum Template {
    /// 4 vertices, 4 triangles.
    Tetrahedron,
    /// 8 vertices, 6 quadrilaterals.
    Cube,
    /// 6 vertices, 8 triangles.
    Octahedron,
}

impl Template {
    fn loops(self) -> (usize, Vec<Vec<u32>>) {
        match self {
            Template::Tetrahedron => (4, TETRA_FACES.iter().map(|t| t.to_vec()).collect()),
            Template::Cube => (8, CUBE_FACES.iter().map(|q| q.to_vec()).collect()),
            Template::Octahedron => (6, OCTA_FACES.iter().map(|t| t.to_vec()).collect()),
        }
    }
}

/// A topologically valid polygon mesh: shells from templates with
/// arbitrary coordinates (integer grid, unit, or any bit pattern: "even
/// replacing the vertex position data with random data would generate a
/// topologically valid result"), some of them reversed, and vertex pairs
/// identified (which keeps every closure constraint and makes non-manifold
/// edges and vertices, and zero-length half-edges).
#[derive(Clone, Arbitrary)]
pub struct Solid {
    /// Shells: template, reversed, and its coordinates (used cyclically).
    pub shells: Vec<(Template, bool, Vec<Coord>)>,
    /// Vertex pairs to identify (indices taken modulo the vertex count).
    pub merges: Vec<(u8, u8)>,
}

impl Solid {
    /// The mesh (always topologically valid).
    pub fn to_mesh(&self) -> PolygonMesh {
        let mut vertices = Vec::new();
        let mut facets = Vec::new();
        for (t, reversed, coords) in self.shells.iter().take(4) {
            let (n, loops) = t.loops();
            let base = vertices.len() as u32;
            for i in 0..n {
                let c = |k: usize| {
                    if coords.is_empty() {
                        // The template's natural position.
                        f64::from(i as u8 >> k & 1)
                    } else {
                        coords[(3 * i + k) % coords.len()].value()
                    }
                };
                vertices.push([c(0), c(1), c(2)]);
            }
            for l in loops {
                let mut l: Vec<u32> = l.iter().map(|v| v + base).collect();
                if *reversed {
                    l.reverse();
                }
                facets.push(Facet::from_loop(&l));
            }
        }
        let n = vertices.len();
        if n > 0 {
            let mut map: Vec<u32> = (0..n as u32).collect();
            for &(x, y) in self.merges.iter().take(4) {
                let (x, y) = (x as usize % n, y as usize % n);
                let (from, target) = (map[x], map[y]);
                for m in map.iter_mut() {
                    if *m == from {
                        *m = target;
                    }
                }
            }
            for f in &mut facets {
                for h in &mut f.half_edges {
                    h.start = map[h.start as usize];
                    h.end = map[h.end as usize];
                }
            }
        }
        PolygonMesh::new(vertices, facets)
    }

    /// The mesh as triangles when every facet is a triangle.
    pub fn to_triangles(&self) -> Option<TriangleMesh> {
        let m = self.to_mesh();
        let mut tris = Vec::new();
        for f in &m.facets {
            let h = &f.half_edges;
            if h.len() != 3 {
                return None;
            }
            tris.push([h[0].start, h[1].start, h[2].start]);
        }
        Some(TriangleMesh::new(m.vertices, tris))
    }
}

impl fmt::Debug for Solid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = self.to_mesh();
        writeln!(f, "PolygonMesh::new(")?;
        writeln!(f, "    vec![")?;
        for p in &m.vertices {
            writeln!(
                f,
                "        [f64::from_bits({:#x}), f64::from_bits({:#x}), f64::from_bits({:#x})],",
                p[0].to_bits(),
                p[1].to_bits(),
                p[2].to_bits()
            )?;
        }
        writeln!(f, "    ],")?;
        writeln!(f, "    vec![")?;
        for fa in &m.facets {
            let l: Vec<u32> = fa.half_edges.iter().map(|h| h.start).collect();
            writeln!(f, "        Facet::from_loop(&{l:?}),")?;
        }
        writeln!(f, "    ],")?;
        write!(f, ")")
    }
}

/// Two solids and an operation.
#[derive(Clone, Arbitrary, Debug)]
pub struct SolidInput {
    /// Operand A.
    pub a: Solid,
    /// Operand B.
    pub b: Solid,
    /// 0 union, 1 intersection, otherwise difference.
    pub op: u8,
}

/// A polygon set and a fill rule for the simplification sweep.
#[derive(Clone, Arbitrary, Debug)]
pub struct SimplifyInput {
    /// The set.
    pub set: Loops,
    /// A second set for the Booleans through simplification.
    pub other: Loops,
    /// The fill rule / operation selector.
    pub rule: u8,
}

/// A smoothing case: a 3D Boolean result and a 2D Boolean result to
/// smooth at a tolerance of `2^(tolerance_exp mod 64 - 48)` relative to
/// the shape's size.
#[derive(Clone, Arbitrary, Debug)]
pub struct SmoothInput {
    /// The 3D operands and operation (the result is what gets smoothed;
    /// operand A itself when the Boolean refuses).
    pub solid: SolidInput,
    /// The 2D operands (their union is what gets smoothed).
    pub planar: [Loops; 2],
    /// The tolerance's exponent.
    pub tolerance_exp: u8,
}

/// A facet for the triangulator (`topology::triangulate_facet`): closed
/// loops lifted onto a plane of 3D space, some vertices identified
/// (touching loops, pinched vertices, loops running back on themselves),
/// and a *plate* built valid by construction: a rectangle with square
/// holes in distinct cells of a grid, for the count and orientation
/// checks that hold on valid facets only.
#[derive(Clone, Arbitrary, Debug)]
pub struct FacetInput {
    /// Loops in the plane (multiplicity: repeated, or reversed if negative).
    pub loops: Loops,
    /// Vertex pairs `(a, b)` (modulo the vertex count): `b` becomes `a`.
    pub identify: Vec<(u8, u8)>,
    /// How the plane sits in space: 0 xy, 1 yz, 2 zx, 3 tilted.
    pub plane: u8,
    /// The plate: `(columns, rows, hole cells)`, cells modulo the grid.
    pub plate: (u8, u8, Vec<(u8, u8)>),
}

impl FacetInput {
    /// Lifts a plane point into space.
    pub fn lift(&self, p: [f64; 2]) -> [f64; 3] {
        match self.plane % 4 {
            0 => [p[0], p[1], 0.0],
            1 => [0.5, p[0], p[1]],
            2 => [p[1], -2.0, p[0]],
            _ => [p[0], p[1], 0.5 * p[0] - 0.25 * p[1] + 1.0],
        }
    }

    /// The loops as positions and half-edges, identified vertices merged.
    pub fn loops_facet(&self) -> (Vec<[f64; 3]>, Vec<(u32, u32)>) {
        let set = self.loops.to_set();
        let positions: Vec<[f64; 3]> = set.vertices().iter().map(|&p| self.lift(p)).collect();
        let n = positions.len();
        let mut alias: Vec<u32> = (0..n as u32).collect();
        if n > 0 {
            for &(a, b) in self.identify.iter().take(8) {
                let (a, b) = (usize::from(a) % n, usize::from(b) % n);
                alias[b] = alias[a];
            }
        }
        let mut half_edges = Vec::new();
        for e in set.edges() {
            let (s, t) = (alias[e.start as usize], alias[e.end as usize]);
            for _ in 0..e.mult.unsigned_abs() {
                half_edges.push(if e.mult > 0 { (s, t) } else { (t, s) });
            }
        }
        (positions, half_edges)
    }

    /// The plate: positions, half-edges (outer boundary anticlockwise in
    /// the plane, holes clockwise), the plane positions, and the hole count.
    pub fn plate_facet(&self) -> (Vec<[f64; 3]>, Vec<(u32, u32)>, Vec<[f64; 2]>, usize) {
        let (w, h) = (
            u32::from(self.plate.0 % 12) + 1,
            u32::from(self.plate.1 % 12) + 1,
        );
        let mut cells: Vec<(u32, u32)> = self
            .plate
            .2
            .iter()
            .take(64)
            .map(|&(i, j)| (u32::from(i) % w, u32::from(j) % h))
            .collect();
        cells.sort_unstable();
        cells.dedup();
        let (fw, fh) = (f64::from(4 * w), f64::from(4 * h));
        let mut plane = vec![[0.0, 0.0], [fw, 0.0], [fw, fh], [0.0, fh]];
        let mut half_edges = vec![(0, 1), (1, 2), (2, 3), (3, 0)];
        for &(i, j) in &cells {
            let (x, y) = (f64::from(4 * i), f64::from(4 * j));
            let b = plane.len() as u32;
            // Clockwise: a hole.
            plane.extend([
                [x + 1.0, y + 1.0],
                [x + 1.0, y + 3.0],
                [x + 3.0, y + 3.0],
                [x + 3.0, y + 1.0],
            ]);
            half_edges.extend([(b, b + 1), (b + 1, b + 2), (b + 2, b + 3), (b + 3, b)]);
        }
        let positions = plane.iter().map(|&p| self.lift(p)).collect();
        (positions, half_edges, plane, cells.len())
    }
}

/// A node of a small CSG tree: a coarse primitive or a Boolean of two or
/// three children, with an optional transform (rotation, a scale that may
/// be non-uniform or mirror, a translation), printed as the JSON script
/// that `umbra csg` reads (`Debug`).
#[derive(Clone, Arbitrary)]
pub enum CsgInput {
    /// A primitive: kind (box, sphere, cylinder, torus), size and segment
    /// parameters, transform.
    Leaf(u8, [u8; 3], u8, CsgTransform),
    /// A Boolean (0 union, 1 intersection, 2 difference, 3 xor, refused
    /// in 3D) of the children, transform.
    Op(u8, Vec<CsgInput>, CsgTransform),
}

/// A node's transform, each part optional.
#[derive(Clone, Copy, Arbitrary)]
pub struct CsgTransform {
    /// Degrees about x, y, z.
    pub rotate: Option<[i8; 3]>,
    /// Scale factors as `k / 8` (0 is refused by the script's checks).
    pub scale: Option<[i8; 3]>,
    /// Translation as `k / 16`.
    pub translate: Option<[i8; 3]>,
}

impl CsgTransform {
    fn json(&self) -> String {
        let mut s = String::new();
        if let Some(r) = self.rotate {
            s += &format!(", \"rotate\": [{}, {}, {}]", r[0], r[1], r[2]);
        }
        if let Some(k) = self.scale {
            let f = |v: i8| f64::from(v) / 8.0;
            s += &format!(", \"scale\": [{}, {}, {}]", f(k[0]), f(k[1]), f(k[2]));
        }
        if let Some(t) = self.translate {
            let f = |v: i8| f64::from(v) / 16.0;
            s += &format!(", \"translate\": [{}, {}, {}]", f(t[0]), f(t[1]), f(t[2]));
        }
        s
    }
}

impl CsgInput {
    /// The script, with at most `depth` levels of operations and two or
    /// three children each (extra children dropped, missing ones a box).
    pub fn json(&self, depth: u32) -> String {
        match self {
            CsgInput::Op(op, children, t) if depth > 0 => {
                let name = ["union", "intersection", "difference", "xor"][usize::from(op % 4)];
                let mut parts: Vec<String> =
                    children.iter().take(3).map(|c| c.json(depth - 1)).collect();
                while parts.len() < 2 {
                    parts.push("{\"box\": {\"size\": 1, \"center\": true}}".to_string());
                }
                format!(
                    "{{\"op\": \"{name}\", \"children\": [{}]{}}}",
                    parts.join(", "),
                    t.json()
                )
            }
            CsgInput::Op(_, _, t) => format!("{{\"box\": {{\"size\": 1}}{}}}", t.json()),
            CsgInput::Leaf(kind, size, seg, t) => {
                let s = |i: usize| 0.25 + f64::from(size[i]) / 64.0;
                let n = 3 + u32::from(seg % 14);
                let shape = match kind % 4 {
                    0 => format!(
                        "\"box\": {{\"size\": [{}, {}, {}], \"center\": {}}}",
                        s(0),
                        s(1),
                        s(2),
                        seg % 2 == 0
                    ),
                    1 => format!("\"sphere\": {{\"radius\": {}, \"segments\": {}}}", s(0), n.max(4)),
                    2 => format!(
                        "\"cylinder\": {{\"radius\": {}, \"height\": {}, \"segments\": {}, \"center\": true}}",
                        s(0),
                        s(1),
                        n
                    ),
                    _ => format!(
                        "\"torus\": {{\"radius\": {}, \"tube\": {}, \"segments\": [{}, {}]}}",
                        s(0) + s(1),
                        s(1) / 2.0,
                        n,
                        3 + u32::from(size[2] % 6)
                    ),
                };
                format!("{{{shape}{}}}", t.json())
            }
        }
    }
}

impl fmt::Debug for CsgInput {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.json(3))
    }
}
