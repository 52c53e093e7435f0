//! File formats through the public API: round trips bit for bit where the
//! format allows (OBJ, OFF, PLY binary and ASCII, ASCII STL for any `f64`,
//! binary STL for `f32` values), the GLB writer checked by an independent
//! glTF reader (the `gltf` crate), real third-party PLY files shipped in the
//! `ply-rs-bw` package, the dispatch by extension, and hostile files:
//! every truncation of small valid files, huge counts, NaN, `1e400`, bad
//! indices, a byte-order mark, non-UTF-8 bytes — never a panic, always one
//! line naming the file and the problem.

use proptest::prelude::*;
use std::path::{Path, PathBuf};
use umbra::{
    mesh_to_3mf, mesh_to_glb, mesh_to_obj, mesh_to_off, mesh_to_ply, mesh_to_stl, parse_obj,
    parse_off, parse_ply, parse_stl, polygon_set_to_svg, read_mesh, read_polygon_set, write_mesh,
    write_mesh_with, write_polygon_set, Facet, FileKind, MeshReadOptions, MeshWriteOptions,
    PolygonMesh, PolygonSet2, ReadOptions, RingOrientation, TriangleMesh, UmbraError,
};

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("umbra-formats-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A closed octahedron scaled by `s` around `c`, with its 8 triangles.
fn octahedron(c: [f64; 3], s: f64) -> PolygonMesh {
    let v = vec![
        [c[0] + s, c[1], c[2]],
        [c[0] - s, c[1], c[2]],
        [c[0], c[1] + s, c[2]],
        [c[0], c[1] - s, c[2]],
        [c[0], c[1], c[2] + s],
        [c[0], c[1], c[2] - s],
    ];
    let t: [[u32; 3]; 8] = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    PolygonMesh::new(v, t.iter().map(|t| Facet::from_loop(t)).collect())
}

/// A unit cube of quads with a square hole through the top facet's
/// surface (a facet with two loops) — closed, 2-manifold.
fn cube_quads() -> PolygonMesh {
    let v: Vec<[f64; 3]> = (0..8u32)
        .map(|i| {
            [
                f64::from(i & 1),
                f64::from((i >> 1) & 1),
                f64::from((i >> 2) & 1),
            ]
        })
        .collect();
    let quads: [[u32; 4]; 6] = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    PolygonMesh::new(v, quads.iter().map(|q| Facet::from_loop(q)).collect())
}

/// The facets as bit patterns of their directed edges' end points,
/// sorted: a multiset independent of vertex numbering.
fn edge_soup(m: &PolygonMesh) -> Vec<[[u64; 3]; 2]> {
    let mut out: Vec<_> = m
        .facets
        .iter()
        .flat_map(|f| f.half_edges.iter())
        .map(|h| {
            [
                m.vertices[h.start as usize].map(f64::to_bits),
                m.vertices[h.end as usize].map(f64::to_bits),
            ]
        })
        .collect();
    out.sort_unstable();
    out
}

fn bits(m: &PolygonMesh) -> Vec<[u64; 3]> {
    m.vertices.iter().map(|p| p.map(f64::to_bits)).collect()
}

fn any_coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1.0e6..1.0e6f64,
        (-1000i32..1000).prop_map(f64::from),
        any::<f64>().prop_filter("valid", |v| umbra::validate_coordinate(*v).is_ok()),
    ]
}

/// A random closed mesh: octahedra at random places and sizes.
fn any_mesh() -> impl Strategy<Value = PolygonMesh> {
    prop::collection::vec(
        (
            [any_coordinate(), any_coordinate(), any_coordinate()],
            1.0e-3..1.0e3f64,
        ),
        1..4,
    )
    .prop_map(|parts| {
        let mut m = PolygonMesh::default();
        for (c, s) in parts {
            let o = octahedron(c, s);
            let base = m.vertices.len() as u32;
            m.vertices.extend(o.vertices);
            m.facets.extend(o.facets.into_iter().map(|mut f| {
                for h in &mut f.half_edges {
                    h.start += base;
                    h.end += base;
                }
                f
            }));
        }
        m
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: test_support::cases(64),
        max_global_rejects: test_support::cases(1024),
        ..ProptestConfig::default()
    })]

    /// OBJ, OFF, PLY (both encodings) and ASCII STL keep every f64 bit for
    /// bit; OBJ, OFF and PLY keep the vertex numbering and facets too.
    #[test]
    fn f64_formats_round_trip_bit_for_bit(m in any_mesh()) {
        let obj = parse_obj(&mesh_to_obj(&m), "m.obj").unwrap();
        prop_assert_eq!(bits(&obj), bits(&m));
        prop_assert_eq!(&obj.facets, &m.facets);
        let off = parse_off(&mesh_to_off(&m), "m.off").unwrap();
        prop_assert_eq!(bits(&off), bits(&m));
        prop_assert_eq!(&off.facets, &m.facets);
        for ascii in [false, true] {
            let ply = parse_ply(&mesh_to_ply(&m, ascii), "m.ply").unwrap();
            prop_assert_eq!(bits(&ply), bits(&m));
            prop_assert_eq!(&ply.facets, &m.facets);
        }
        let stl = parse_stl(&mesh_to_stl(&m, true).unwrap(), "m.stl").unwrap();
        prop_assert_eq!(edge_soup(&stl.to_polygon_mesh()), edge_soup(&m));
    }

    /// Binary STL keeps f32 values bit for bit and rounds others to the
    /// nearest f32.
    #[test]
    fn binary_stl_rounds_to_f32(m in any_mesh()) {
        let mut rounded = m.clone();
        for p in &mut rounded.vertices {
            for x in p.iter_mut() {
                *x = f64::from(*x as f32);
            }
        }
        // Only meshes whose rounding keeps distinct vertices distinct
        // weld back to the same shape.
        let distinct = |mesh: &PolygonMesh| {
            let mut b = bits(mesh);
            b.sort_unstable();
            b.dedup();
            b.len()
        };
        prop_assume!(distinct(&rounded) == distinct(&m));
        prop_assume!(rounded.vertices.iter().flatten().all(|x| x.is_finite()));
        let bytes = mesh_to_stl(&m, false).unwrap();
        let back = parse_stl(&bytes, "m.stl").unwrap();
        prop_assert_eq!(edge_soup(&back.to_polygon_mesh()), edge_soup(&rounded));
        // And the f32 mesh round-trips exactly, but for the triangles
        // that welding gave a repeated corner (distinct vertices at one
        // position, as on a tiny octahedron far from the origin): such a
        // facet balances itself and triangulates to nothing (section 4.8),
        // so writing drops it, and a file left without triangles reads as
        // the empty mesh. A property-test find at `UMBRA_PROPTEST_SCALE=40`.
        let written = mesh_to_stl(&back.to_polygon_mesh(), false).unwrap();
        let proper: Vec<[u32; 3]> = back
            .triangles
            .iter()
            .copied()
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
            .collect();
        if proper.is_empty() {
            prop_assert_eq!(parse_stl(&written, "m.stl").unwrap(), TriangleMesh::default());
        } else if proper.len() == back.triangles.len() {
            prop_assert_eq!(parse_stl(&written, "m.stl").unwrap(), back);
        } else {
            let again = parse_stl(&written, "m.stl").unwrap();
            let kept = TriangleMesh::new(back.vertices.clone(), proper);
            prop_assert_eq!(
                edge_soup(&again.to_polygon_mesh()),
                edge_soup(&kept.to_polygon_mesh())
            );
        }
    }
}

/// The find of `binary_stl_rounds_to_f32`: an octahedron of size 1e-3
/// centred at (-1.7e31, -1.1e35, 0), whose four corners off the z axis are
/// one position. Binary STL welds them into one vertex, so every triangle
/// read back has a repeated corner; written again, each triangulates to
/// nothing, and the file, without triangles, reads as the empty mesh.
#[test]
fn welded_away_octahedron_writes_an_empty_stl() {
    let o = octahedron(
        [
            -1.680_882_511_638_074_5e31,
            -1.087_961_376_052_089_2e35,
            0.0,
        ],
        1e-3,
    );
    let back = parse_stl(&mesh_to_stl(&o, false).unwrap(), "o.stl").unwrap();
    assert_eq!(back.vertices.len(), 3);
    assert_eq!(back.triangles.len(), 8);
    assert!(back
        .triangles
        .iter()
        .all(|t| t[0] == t[1] || t[1] == t[2] || t[2] == t[0]));
    let written = mesh_to_stl(&back.to_polygon_mesh(), false).unwrap();
    assert_eq!(written.len(), 84);
    assert_eq!(
        parse_stl(&written, "o.stl").unwrap(),
        TriangleMesh::default()
    );
}

#[test]
fn files_round_trip_through_the_dispatch() {
    let dir = temp_dir("dispatch");
    let m = cube_quads();
    for (name, text) in [
        ("c.obj", false),
        ("c.off", false),
        ("c.ply", false),
        ("c_ascii.ply", true),
        ("c.stl", false),
        ("c_ascii.stl", true),
    ] {
        let path = dir.join(name);
        write_mesh_with(&path, &m, MeshWriteOptions { text }).unwrap();
        let back = read_mesh(&path, MeshReadOptions::default(), true).unwrap();
        assert_eq!(
            umbra::mesh_signed_volume(&back),
            1.0,
            "{name}: the unit cube's volume"
        );
        if !name.ends_with(".stl") {
            assert_eq!(bits(&back), bits(&m), "{name}");
        }
    }
    // Binary by default.
    write_mesh(&dir.join("d.stl"), &m).unwrap();
    let bytes = std::fs::read(dir.join("d.stl")).unwrap();
    assert_eq!(bytes.len(), 84 + 12 * 50);
    assert!(!bytes.starts_with(b"solid"));
    write_mesh(&dir.join("d.ply"), &m).unwrap();
    assert!(std::fs::read(dir.join("d.ply"))
        .unwrap()
        .starts_with(b"ply\nformat binary_little_endian 1.0\n"));
    // glTF (binary and JSON) and 3MF read back as the cube's triangles, closed (the
    // unit cube's coordinates are `f32` values, which glTF keeps exactly;
    // 3MF keeps every `f64`).
    for name in ["c.glb", "c.gltf", "c.3mf"] {
        let path = dir.join(name);
        write_mesh(&path, &m).unwrap();
        let back = read_mesh(&path, MeshReadOptions::default(), true).unwrap();
        assert_eq!(back.facets.len(), 12, "{name}");
        let (mut got, mut want) = (bits(&back), bits(&m));
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want, "{name}");
        assert_eq!(test_support::measure::polygon_mesh_volume(&back), 1.0);
    }
    let mut square = PolygonSet2::new();
    square.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    let svg = dir.join("s.svg");
    assert_eq!(
        write_polygon_set(&svg, &square, RingOrientation::ByRole).unwrap(),
        0
    );
    let e = read_polygon_set(&svg, ReadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("'.svg' (SVG) can be written but not read"),
        "{e}"
    );
    // A mesh to a 2D file and back.
    let e = write_mesh(&dir.join("x.svg"), &m).unwrap_err().to_string();
    assert!(e.contains("expected a 3D"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn every_extension_is_listed_in_the_message() {
    let e = FileKind::from_path(Path::new("x.dxf"))
        .unwrap_err()
        .to_string();
    for kind in FileKind::ALL {
        assert!(
            e.contains(&format!(".{} ", kind.extension()))
                || e.contains(&format!(".{})", kind.extension()))
                || e.contains(&format!(".{},", kind.extension())),
            "{kind:?}: {e}"
        );
        assert_eq!(
            FileKind::from_path(Path::new(&format!("a.{}", kind.extension().to_uppercase())))
                .unwrap(),
            kind
        );
    }
}

/// The GLB read back by the `gltf` crate: structure, bounds, data.
#[test]
fn glb_is_valid_gltf() {
    let mut m = octahedron([1.5, -2.0, 0.25], 0.5);
    m.vertices[0][0] = 0.1; // not an f32: rounded
    let bytes = mesh_to_glb(&m).unwrap();
    assert_eq!(bytes.len() % 4, 0);
    let glb = gltf::Glb::from_slice(&bytes).unwrap();
    assert_eq!(glb.header.length as usize, bytes.len());
    let doc = gltf::Gltf::from_slice(&bytes).unwrap();
    let blob = doc.blob.clone().unwrap();
    let mesh = doc.meshes().next().unwrap();
    let prim = mesh.primitives().next().unwrap();
    assert_eq!(prim.mode(), gltf::mesh::Mode::Triangles);
    let reader = prim.reader(|_| Some(&blob));
    let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
    let want: Vec<[f32; 3]> = m.vertices.iter().map(|p| p.map(|x| x as f32)).collect();
    assert_eq!(positions, want);
    let indices: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
    let tris: Vec<u32> = m
        .facets
        .iter()
        .flat_map(|f| f.loops().into_iter().next().unwrap())
        .collect();
    assert_eq!(indices, tris);
    let acc = prim.get(&gltf::Semantic::Positions).unwrap();
    let min: Vec<f32> = serde_json_values(acc.min().unwrap());
    let max: Vec<f32> = serde_json_values(acc.max().unwrap());
    for axis in 0..3 {
        let lo = want.iter().map(|p| p[axis]).fold(f32::INFINITY, f32::min);
        let hi = want
            .iter()
            .map(|p| p[axis])
            .fold(f32::NEG_INFINITY, f32::max);
        assert_eq!((min[axis], max[axis]), (lo, hi), "axis {axis}");
    }
    // An empty mesh is a valid document without buffers.
    let empty = mesh_to_glb(&PolygonMesh::default()).unwrap();
    let doc = gltf::Gltf::from_slice(&empty).unwrap();
    assert_eq!(doc.meshes().count(), 0);
    // A coordinate beyond f32 is refused.
    let mut far = octahedron([0.0; 3], 1.0);
    far.vertices[2][1] = -1e39;
    let e = mesh_to_glb(&far).unwrap_err().to_string();
    assert!(e.contains("cannot write glTF: vertex 2: y = -1e39"), "{e}");
}

fn serde_json_values(v: gltf::json::Value) -> Vec<f32> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap() as f32)
        .collect()
}

#[test]
fn three_mf_holds_every_triangle() {
    let m = cube_quads();
    let bytes = mesh_to_3mf(&m).unwrap();
    assert!(bytes.starts_with(b"PK"));
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
    let mut model = String::new();
    std::io::Read::read_to_string(&mut zip.by_name("3D/3dmodel.model").unwrap(), &mut model)
        .unwrap();
    assert_eq!(model.matches("<vertex ").count(), 8);
    assert_eq!(model.matches("<triangle ").count(), 12);
}

#[test]
fn svg_flips_y_and_fills_by_winding() {
    let mut s = PolygonSet2::new();
    s.add_loop(&[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]);
    s.add_loop(&[[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]]);
    let (svg, orphans) = polygon_set_to_svg(&s).unwrap();
    assert_eq!(orphans, 0);
    assert!(svg.contains("fill-rule=\"nonzero\""));
    assert!(svg.contains("viewBox=\"-0.2 -4.2 4.4 4.4\""), "{svg}");
    // Outer ring counter-clockwise in y-up is clockwise in the y-down
    // picture; the hole's direction is the opposite of the outer's.
    let d = svg
        .split(" d=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap();
    let rings: Vec<Vec<[f64; 2]>> = d
        .split('Z')
        .filter(|r| !r.is_empty())
        .map(|r| {
            r.split(['M', 'L'])
                .filter(|p| !p.is_empty())
                .map(|p| {
                    let mut xy = p.split(' ').map(|x| x.parse::<f64>().unwrap());
                    [xy.next().unwrap(), xy.next().unwrap()]
                })
                .collect()
        })
        .collect();
    assert_eq!(rings.len(), 2);
    let area = |r: &Vec<[f64; 2]>| umbra::ring_signed_area(r);
    assert_eq!(area(&rings[0]), -16.0);
    assert_eq!(area(&rings[1]), 1.0);
    assert!(rings.iter().flatten().all(|p| p[1] <= 0.0));
}

/// The directory of the `ply-rs-bw` package's example files, found in
/// Cargo's registry.
fn ply_examples() -> Option<PathBuf> {
    let home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo")))?;
    let src = home.join("registry").join("src");
    for index in std::fs::read_dir(src).ok()?.flatten() {
        let mut found: Vec<PathBuf> = std::fs::read_dir(index.path())
            .ok()?
            .flatten()
            .map(|e| e.path())
            .filter(|p| {
                p.file_name()
                    .and_then(|n| n.to_str())
                    .is_some_and(|n| n.starts_with("ply-rs-bw-4."))
            })
            .collect();
        found.sort();
        if let Some(p) = found.pop() {
            return Some(p.join("example_plys"));
        }
    }
    None
}

/// Third-party PLY files: the tetrahedron in ASCII, big and little endian
/// gives one mesh; Greg Turk's cube (mixed triangles and quads, colours,
/// an extra `edge` element) is closed with volume 1.
#[test]
fn third_party_ply_files() {
    let Some(dir) = ply_examples() else {
        eprintln!("NOTE: ply-rs-bw's example files not found in Cargo's registry; skipped");
        return;
    };
    let read = |name: &str| read_mesh(&dir.join(name), MeshReadOptions::default(), true);
    let tet = read("tetrahedron_ascii.ply").unwrap();
    assert_eq!((tet.vertices.len(), tet.facets.len()), (4, 4));
    for name in [
        "tetrahedron_big_endian.ply",
        "tetrahedron_little_endian.ply",
    ] {
        assert_eq!(read(name).unwrap(), tet, "{name}");
    }
    let cube = read("greg_turk_example2_ok_ascii.ply").unwrap();
    assert_eq!(cube.facets.len(), 7);
    assert_eq!(umbra::mesh_signed_volume(&cube).abs(), 1.0);
    // An open house: the error names an open edge by its positions.
    let e = read("house_ok_ascii.ply").unwrap_err().to_string();
    assert!(
        e.contains("shape boundary closure violated: the edge from vertex"),
        "{e}"
    );
}

/// Every prefix of small valid files, in every format: a mesh or a one-line
/// error naming the file; never a panic.
#[test]
fn every_truncation_is_an_error_or_a_mesh() {
    let m = cube_quads();
    let files: Vec<(&str, Vec<u8>)> = vec![
        ("t.obj", mesh_to_obj(&m).into_bytes()),
        ("t.off", mesh_to_off(&m).into_bytes()),
        ("t.ply", mesh_to_ply(&m, false)),
        ("t.ply", mesh_to_ply(&m, true)),
        ("t.stl", mesh_to_stl(&m, false).unwrap()),
        ("t.stl", mesh_to_stl(&m, true).unwrap()),
    ];
    for (name, bytes) in &files {
        for end in 0..bytes.len() {
            let cut = &bytes[..end];
            let result = parse_any(name, cut);
            if let Err(e) = result {
                let text = e.to_string();
                assert!(
                    text.starts_with(&format!("{name}: ")) && !text.contains('\n'),
                    "{name} cut at {end}: {text}"
                );
            }
        }
    }
}

fn parse_any(name: &str, bytes: &[u8]) -> Result<PolygonMesh, UmbraError> {
    let text = || String::from_utf8_lossy(bytes).into_owned();
    match Path::new(name).extension().and_then(|e| e.to_str()) {
        Some("obj") => parse_obj(&text(), name),
        Some("off") => parse_off(&text(), name),
        Some("ply") => parse_ply(bytes, name),
        Some("stl") => parse_stl(bytes, name).map(|t: TriangleMesh| t.to_polygon_mesh()),
        _ => unreachable!(),
    }
}

/// Reads `bytes` as a file named `name` with the closure check, returning
/// the message.
fn read_error(dir: &Path, name: &str, bytes: &[u8]) -> String {
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    let e = read_mesh(&path, MeshReadOptions::default(), true)
        .map(|_| "no error".to_string())
        .unwrap_or_else(|e| e.to_string());
    assert!(!e.contains('\n'), "{e}");
    e
}

#[test]
fn hostile_files_get_one_line_naming_file_place_and_problem() {
    let dir = temp_dir("hostile");
    let d = |name: &str| dir.join(name).display().to_string();
    let mut huge_stl = vec![0u8; 84];
    huge_stl[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let cases: Vec<(&str, Vec<u8>, String)> = vec![
        ("huge.stl", huge_stl, "the header says 4294967295 triangles (214748364834 bytes) but the file has 84 bytes".into()),
        ("huge.off", b"OFF\n99999999 99999999 0\n0 0 0\n".to_vec(), "expected 99999999 vertices, found 1".into()),
        ("huge.ply", b"ply\nformat binary_little_endian 1.0\nelement face 3000000000\nproperty list uchar int vertex_indices\nend_header\n\x03".to_vec(), "3000000000 'face' element(s) of at least 1 byte(s) each, more than the 1 byte(s)".into()),
        ("nan.stl", b"solid a\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid a\n".to_vec(), "vertex 1 (line 2): x coordinate NaN is not finite".into()),
        ("big.obj", b"v 0 0 0\nv 1e400 0 0\n".to_vec(), "line 2: '1e400' overflows f64".into()),
        ("big.off", b"OFF\n1 0 0\n0 -1e999 0\n".to_vec(), "line 3: '-1e999' overflows f64".into()),
        ("dangling.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 3\nf 1 3 9\n".to_vec(), "dangling index: face 2 (line 6) refers to vertex 9, but there are only 3 vertices".into()),
        ("dangling.off", b"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 9\n".to_vec(), "dangling index: face 2 (line 7) refers to vertex 9".into()),
        ("open.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\n".to_vec(), "the edge from vertex 1 (line 1) (0.0, 0.0, 0.0) to vertex 3 (line 3) (0.0, 1.0, 0.0) has 0 half-edge(s) one way and 1 the other".into()),
        ("latin1.obj", b"v 0 0 0\n# caf\xe9\n".to_vec(), "malformed OBJ: line 2: not UTF-8 text (invalid byte 0xe9 at offset 13)".into()),
        ("latin1.off", b"OFF\n\xe9".to_vec(), "malformed OFF: line 2: not UTF-8".into()),
        ("bom.off", b"\xef\xbb\xbfOFF\n0 0 0\n".to_vec(), "no error".into()),
        ("utf16.stl", b"\xff\xfes\x00o\x00".to_vec(), "too short for a binary STL".into()),
        ("binary.ply", b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n\x00\x01\x02\x03\x04\x05\x06\n".to_vec(), "line 8: ".into()),
    ];
    for (name, bytes, want) in &cases {
        let e = read_error(&dir, name, bytes);
        if want == "no error" {
            assert_eq!(&e, want, "{name}");
            continue;
        }
        assert!(e.starts_with(&format!("{}: ", d(name))), "{name}: {e}");
        assert!(e.contains(want.as_str()), "{name}: want {want:?} in {e}");
    }
    let latin = dir.join("latin1.geojson");
    std::fs::write(&latin, b"{\"type\": \"Polygon\xe9\"}").unwrap();
    let e = read_polygon_set(&latin, ReadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("malformed GeoJSON: line 1: not UTF-8"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

/// An OBJ starting with a byte-order mark reads exactly as without it.
#[test]
fn byte_order_marks_are_dropped() {
    let obj = include_str!("../../../../examples/cube.obj");
    let plain = parse_obj(obj, "c.obj").unwrap();
    let bom = parse_obj(&format!("\u{feff}{obj}"), "c.obj").unwrap();
    assert_eq!(bom, plain);
    let off = include_str!("../../../../examples/cube_shifted.off");
    assert_eq!(
        parse_off(&format!("\u{feff}{off}"), "c.off").unwrap(),
        parse_off(off, "c.off").unwrap()
    );
    let stl = mesh_to_stl(&plain, true).unwrap();
    let mut with_bom = "\u{feff}".as_bytes().to_vec();
    with_bom.extend_from_slice(&stl);
    assert_eq!(
        parse_stl(&with_bom, "c.stl").unwrap(),
        parse_stl(&stl, "c.stl").unwrap()
    );
    let ply = mesh_to_ply(&plain, true);
    let mut with_bom = "\u{feff}".as_bytes().to_vec();
    with_bom.extend_from_slice(&ply);
    assert_eq!(parse_ply(&with_bom, "c.ply").unwrap(), plain);
    // An invisible character elsewhere is shown escaped.
    let e = parse_off("\u{200b}OFF\n", "z.off").unwrap_err().to_string();
    assert!(e.contains("\\u{200b}OFF"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(256)))]

    /// Random bytes, and valid files with random bytes overwritten: a mesh
    /// or one line naming the file, never a panic.
    #[test]
    fn garbage_never_panics(
        which in 0usize..6,
        edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 0..8),
        tail in prop::collection::vec(any::<u8>(), 0..64),
    ) {
        let m = cube_quads();
        let (name, mut bytes) = match which {
            0 => ("g.obj", mesh_to_obj(&m).into_bytes()),
            1 => ("g.off", mesh_to_off(&m).into_bytes()),
            2 => ("g.ply", mesh_to_ply(&m, false)),
            3 => ("g.ply", mesh_to_ply(&m, true)),
            4 => ("g.stl", mesh_to_stl(&m, false).unwrap()),
            _ => ("g.stl", mesh_to_stl(&m, true).unwrap()),
        };
        for (i, b) in &edits {
            let at = i.index(bytes.len());
            bytes[at] = *b;
        }
        bytes.extend_from_slice(&tail);
        if let Err(e) = parse_any(name, &bytes) {
            let text = e.to_string();
            prop_assert!(text.starts_with(&format!("{name}: ")) && !text.contains('\n'), "{}", text);
        }
    }
}

/// `bytes`, a 3MF package, with every `<triangle .../>` of its model part
/// removed (its vertices kept).
fn three_mf_without_triangles(bytes: Vec<u8>) -> Vec<u8> {
    use std::io::{Read, Write};
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
    let mut out = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for i in 0..zip.len() {
        let mut entry = zip.by_index(i).unwrap();
        let name = entry.name().unwrap().to_string();
        let mut text = String::new();
        entry.read_to_string(&mut text).unwrap();
        if name == "3D/3dmodel.model" {
            text = text
                .lines()
                .filter(|l| !l.contains("<triangle "))
                .collect::<Vec<_>>()
                .join("\n");
        }
        out.start_file(name, zip::write::SimpleFileOptions::default())
            .unwrap();
        out.write_all(text.as_bytes()).unwrap();
    }
    out.finish().unwrap().into_inner()
}

/// A file of vertices without faces (a point cloud, an OBJ of lines) is
/// no solid: every reader that can express it refuses it with one line
/// naming the file and "no facets", where it used to read as an empty
/// solid and make every result silently empty. A file of neither (what
/// the writers write for the empty result of a Boolean, a binary STL of
/// zero triangles) is still the empty solid.
#[test]
fn vertices_without_faces_are_refused_and_nothing_is_the_empty_solid() {
    let dir = temp_dir("no-facets");
    let points = PolygonMesh::new(
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        Vec::new(),
    );
    let ply_ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nelement face 0\nproperty list uchar uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "lines.obj",
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3 1\n".to_vec(),
            "malformed OBJ: no facets: 3 vertices but no faces",
        ),
        (
            "points.obj",
            mesh_to_obj(&points).into_bytes(),
            "malformed OBJ: no facets: 3 vertices but no faces",
        ),
        (
            "points.off",
            b"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n".to_vec(),
            "malformed OFF: no facets: 3 vertices but no faces",
        ),
        (
            "ascii.ply",
            ply_ascii.as_bytes().to_vec(),
            "malformed PLY: no facets: 3 vertices but no faces",
        ),
        (
            "binary.ply",
            mesh_to_ply(&points, false),
            "malformed PLY: no facets: 3 vertices but no faces",
        ),
        (
            "cube.3mf",
            three_mf_without_triangles(mesh_to_3mf(&cube_quads()).unwrap()),
            "malformed 3MF: no facets: 8 vertices but no triangles",
        ),
    ];
    for (name, bytes, problem) in cases {
        let path = dir.join(name);
        std::fs::write(&path, &bytes).unwrap();
        let want = format!(
            "{}: {problem} (a solid needs facets; a file of neither is the empty solid)",
            path.display()
        );
        for check in [true, false] {
            let e = read_mesh(&path, MeshReadOptions::default(), check).unwrap_err();
            assert_eq!(e.to_string(), want, "{name}");
        }
    }
    assert!(parse_obj("v 1 2 3\n", "p.obj")
        .unwrap_err()
        .to_string()
        .starts_with("p.obj: malformed OBJ: no facets: 1 vertices but no faces"));
    assert!(parse_off("OFF\n1 0 0\n1 2 3\n", "p.off").is_err());
    assert!(parse_ply(&mesh_to_ply(&points, true), "p.ply").is_err());

    // Nothing at all is the empty solid, in every format that can say it.
    let empty = PolygonMesh::default();
    let nothing: Vec<(&str, Vec<u8>)> = vec![
        ("empty.obj", mesh_to_obj(&empty).into_bytes()),
        ("empty.off", mesh_to_off(&empty).into_bytes()),
        ("empty.ply", mesh_to_ply(&empty, false)),
        ("empty-ascii.ply", mesh_to_ply(&empty, true)),
        ("empty.stl", mesh_to_stl(&empty, false).unwrap()),
        ("empty-ascii.stl", mesh_to_stl(&empty, true).unwrap()),
        ("empty.glb", mesh_to_glb(&empty).unwrap()),
    ];
    for (name, bytes) in nothing {
        let path = dir.join(name);
        std::fs::write(&path, &bytes).unwrap();
        let m = read_mesh(&path, MeshReadOptions::default(), true).unwrap();
        assert_eq!(m, PolygonMesh::default(), "{name}");
    }
    // A binary STL of zero triangles: its 84 bytes, count 0.
    let stl = mesh_to_stl(&empty, false).unwrap();
    assert_eq!((stl.len(), &stl[80..]), (84, &[0u8; 4][..]));
}
