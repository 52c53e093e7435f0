//! Pictures judged by their pixels: coverage of the frame by a box in each
//! view against the box's projected area, shading levels, the highlight
//! colour present exactly when the mesh check finds problems, winding
//! shades against an analytic winding, SVG well-formed, determinism,
//! size limits.

use umbra::{
    render_mesh, render_mesh_svg, render_polygons, render_polygons_svg, Facet, Image, PolygonMesh,
    PolygonSet2, RenderError, RenderOptions, Style, View, HIGHLIGHT,
};

const WHITE: [u8; 3] = [255, 255, 255];

/// An axis-aligned box `[0, x] x [0, y] x [0, z]`, facets facing out.
fn cuboid(x: f64, y: f64, z: f64) -> PolygonMesh {
    let v = vec![
        [0.0, 0.0, 0.0],
        [x, 0.0, 0.0],
        [x, y, 0.0],
        [0.0, y, 0.0],
        [0.0, 0.0, z],
        [x, 0.0, z],
        [x, y, z],
        [0.0, y, z],
    ];
    let loops = [
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect())
}

fn opts(view: View, width: u32, height: u32) -> RenderOptions {
    RenderOptions {
        view,
        width,
        height,
        ..RenderOptions::default()
    }
}

fn pixels(image: &Image) -> impl Iterator<Item = [u8; 3]> + '_ {
    image.rgb().chunks(3).map(|c| [c[0], c[1], c[2]])
}

fn covered(image: &Image) -> usize {
    pixels(image).filter(|&c| c != WHITE).count()
}

fn count(image: &Image, colour: [u8; 3]) -> usize {
    pixels(image).filter(|&c| c == colour).count()
}

/// The margin of the frame (6% of the shorter side, floored).
fn margin(w: u32, h: u32) -> f64 {
    (f64::from(w.min(h)) * 0.06).floor()
}

#[test]
fn box_coverage_in_each_axis_view_matches_the_fitted_rectangle() {
    // A 2 x 1 x 0.5 box: front shows x by z, top x by y, side y by z.
    let mesh = cuboid(2.0, 1.0, 0.5);
    let (w, h) = (400u32, 300u32);
    let m = margin(w, h);
    for (view, ext) in [
        (View::Front, [2.0, 0.5]),
        (View::Top, [2.0, 1.0]),
        (View::Side, [1.0, 0.5]),
    ] {
        let image = render_mesh(&mesh, &opts(view, w, h)).unwrap();
        let scale = ((f64::from(w) - 2.0 * m) / ext[0]).min((f64::from(h) - 2.0 * m) / ext[1]);
        let expect = ext[0] * scale * ext[1] * scale;
        let got = covered(&image) as f64;
        assert!(
            (got - expect).abs() <= 2.0 * (ext[0] + ext[1]) * scale + 4.0,
            "{view:?}: {got} pixels covered, expected about {expect}"
        );
        // One face seen flat: a single shade.
        let shades: std::collections::BTreeSet<[u8; 3]> =
            pixels(&image).filter(|&c| c != WHITE).collect();
        assert_eq!(shades.len(), 1, "{view:?}");
    }
}

#[test]
fn box_in_iso_view_has_three_shades_and_fills_a_fair_share() {
    let image = render_mesh(&cuboid(1.0, 1.0, 1.0), &opts(View::Iso, 300, 300)).unwrap();
    let shades: std::collections::BTreeSet<[u8; 3]> =
        pixels(&image).filter(|&c| c != WHITE).collect();
    assert!(shades.len() >= 3, "{shades:?}");
    // The projected cube is a hexagon of area sqrt(3) * s^2 * ... fitted
    // to the frame: between a quarter and the whole frame.
    let share = covered(&image) as f64 / 90_000.0;
    assert!((0.3..0.9).contains(&share), "{share}");
    // The three visible faces are about equally large.
    for s in &shades {
        let n = count(&image, *s) as f64 / covered(&image) as f64;
        assert!((0.25..0.42).contains(&n), "{s:?}: {n}");
    }
}

#[test]
fn highlight_appears_exactly_when_the_check_finds_problems() {
    let highlight = |mesh: &PolygonMesh| {
        let o = RenderOptions {
            highlight: true,
            ..opts(View::Iso, 200, 150)
        };
        let png = count(&render_mesh(mesh, &o).unwrap(), HIGHLIGHT);
        let svg = render_mesh_svg(mesh, &o).unwrap().contains("#e61478");
        (png, svg)
    };
    let cube = cuboid(1.0, 1.0, 1.0);
    assert!(cube.check().is_valid() && cube.check().two_manifold == Some(true));
    assert_eq!(highlight(&cube), (0, false));

    // An open box (the top removed): not topologically valid, four edges
    // unbalanced.
    let mut open = cube.clone();
    open.facets.remove(1);
    assert!(open.check_topology().is_err());
    let (n, svg) = highlight(&open);
    assert!(n > 100 && svg, "{n}");

    // A box with a dangling fin (a doubled triangle on an edge): valid
    // topology, non-manifold edge.
    let mut fin = cube.clone();
    let apex = fin.vertices.len() as u32;
    fin.vertices.push([2.0, 0.0, 2.0]);
    fin.facets.push(Facet::from_loop(&[5, 6, apex]));
    fin.facets.push(Facet::from_loop(&[6, 5, apex]));
    let report = fin.manifold_report().unwrap();
    assert!(!report.is_two_manifold());
    let (n, svg) = highlight(&fin);
    assert!(n > 100 && svg, "{n}");

    // Two boxes crossing: intersecting facet pairs, but 2-manifold.
    let mut two = cube.clone();
    let b = cuboid(1.0, 1.0, 1.0);
    let off = two.vertices.len() as u32;
    two.vertices.extend(
        b.vertices
            .iter()
            .map(|p| [p[0] + 0.5, p[1] + 0.5, p[2] + 0.5]),
    );
    two.facets.extend(b.facets.iter().map(|f| {
        let mut f = f.clone();
        for h in &mut f.half_edges {
            h.start += off;
            h.end += off;
        }
        f
    }));
    assert!(two.manifold_report().unwrap().is_two_manifold());
    assert!(!two.self_intersections().unwrap().is_empty());
    let (n, svg) = highlight(&two);
    assert!(n > 100 && svg, "{n}");

    // Without --highlight no pixel has the colour, whatever the mesh.
    assert_eq!(
        count(
            &render_mesh(&open, &opts(View::Iso, 200, 150)).unwrap(),
            HIGHLIGHT
        ),
        0
    );
}

#[test]
fn highlight_marks_the_unbalanced_edges_of_an_invalid_mesh() {
    let mut mesh = cuboid(1.0, 1.0, 1.0);
    mesh.facets[0].half_edges.pop();
    let o = RenderOptions {
        highlight: true,
        ..RenderOptions::default()
    };
    assert!(count(&render_mesh(&mesh, &o).unwrap(), HIGHLIGHT) > 100);
    // Facets referring to missing vertices: refused for highlighting.
    mesh.facets.push(Facet::from_loop(&[0, 1, 99]));
    assert!(matches!(
        render_mesh(&mesh, &o),
        Err(RenderError::Unsupported(_))
    ));
}

#[test]
fn output_is_deterministic_across_runs_and_thread_counts() {
    let mesh = umbra::uv_sphere(1.0, 48, 24).unwrap();
    let o = opts(View::Iso, 320, 240);
    let pool = |n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
    };
    let one = pool(1).install(|| render_mesh(&mesh, &o).unwrap().to_png().unwrap());
    let two = pool(2).install(|| render_mesh(&mesh, &o).unwrap().to_png().unwrap());
    let again = render_mesh(&mesh, &o).unwrap().to_png().unwrap();
    assert_eq!(one, two);
    assert_eq!(one, again);
    assert_eq!(
        render_mesh_svg(&mesh, &o).unwrap(),
        render_mesh_svg(&mesh, &o).unwrap()
    );
    let set = figure_eight();
    let p1 = pool(1).install(|| render_polygons(&set, &o).unwrap());
    let p2 = pool(2).install(|| render_polygons(&set, &o).unwrap());
    assert_eq!(p1, p2);
}

#[test]
fn sizes_are_honoured_and_hostile_sizes_refused_without_allocating() {
    let mesh = cuboid(1.0, 1.0, 1.0);
    for (w, h) in [(1, 1), (7, 300), (640, 480), (1000, 10)] {
        let image = render_mesh(&mesh, &opts(View::Top, w, h)).unwrap();
        assert_eq!((image.width(), image.height()), (w, h));
        assert_eq!(image.rgb().len(), (w * h * 3) as usize);
        let png = image.to_png().unwrap();
        assert_eq!(
            &png[16..24],
            &[w.to_be_bytes(), h.to_be_bytes()].concat()[..]
        );
    }
    for (w, h) in [
        (0, 0),
        (0, 10),
        (100_000, 100_000),
        (16_384, 16_384),
        (u32::MAX, 1),
    ] {
        let e = render_mesh(&mesh, &opts(View::Iso, w, h)).unwrap_err();
        assert!(matches!(e, RenderError::BadSize { .. }), "{e}");
        assert!(e.to_string().contains(&format!("{w}x{h}")), "{e}");
        assert!(render_polygons(&figure_eight(), &opts(View::Iso, w, h)).is_err());
    }
}

#[test]
fn bad_coordinates_and_bad_indices_are_errors_or_skipped_never_panics() {
    let mut mesh = cuboid(1.0, 1.0, 1.0);
    mesh.vertices[0][2] = f64::NAN;
    assert!(matches!(
        render_mesh(&mesh, &RenderOptions::default()),
        Err(RenderError::InvalidShape(_))
    ));
    let mut mesh = cuboid(1.0, 1.0, 1.0);
    mesh.facets.push(Facet::from_loop(&[0, 1, 99]));
    assert!(render_mesh(&mesh, &RenderOptions::default()).is_ok());
    assert!(render_mesh_svg(&mesh, &RenderOptions::default()).is_ok());
    // Huge but valid coordinates project without overflow.
    let big = cuboid(f64::MAX / 4.0, 1e300, f64::MAX / 8.0);
    let image = render_mesh(&big, &opts(View::Front, 100, 100)).unwrap();
    assert!(covered(&image) > 0);
    // Empty shapes give an empty frame.
    assert_eq!(
        covered(&render_mesh(&PolygonMesh::default(), &RenderOptions::default()).unwrap()),
        0
    );
    assert_eq!(
        covered(&render_polygons(&PolygonSet2::new(), &RenderOptions::default()).unwrap()),
        0
    );
}

/// A figure eight: one loop crossing itself, winding +1 in one lobe and
/// -1 in the other.
fn figure_eight() -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    s.add_loop(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
    s
}

/// The winding number of `p` around the directed edges, by the exact
/// crossing rule (an independent oracle).
fn winding(set: &PolygonSet2, p: [f64; 2]) -> i64 {
    let mut w = 0;
    for e in set.edges() {
        let (a, b) = set.edge_points(e);
        if (a[1] <= p[1]) != (b[1] <= p[1]) {
            let side = umbra::orient2d(a, b, p);
            if b[1] > a[1] && side == std::cmp::Ordering::Greater {
                w += i64::from(e.mult);
            } else if b[1] <= a[1] && side == std::cmp::Ordering::Less {
                w -= i64::from(e.mult);
            }
        }
    }
    w
}

#[test]
fn cells_of_equal_winding_share_one_shade() {
    // Two overlapping squares (winding 2 where both), a figure eight and
    // an edge of multiplicity 3.
    let mut set = PolygonSet2::new();
    set.add_loop(&[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]);
    set.add_loop(&[[2.0, 1.0], [6.0, 1.0], [6.0, 3.0], [2.0, 3.0]]);
    let mut eight = figure_eight();
    eight = {
        let (v, e) = eight.into_parts();
        PolygonSet2::from_parts(v.iter().map(|p| [p[0] + 1.0, p[1] + 5.0]).collect(), e)
    };
    set.append(&eight);
    let a = set.add_vertex([7.0, 0.0]);
    let b = set.add_vertex([9.0, 0.0]);
    let c = set.add_vertex([8.0, 2.0]);
    set.add_edge_mult(a, b, 3);
    set.add_edge_mult(b, c, 3);
    set.add_edge_mult(c, a, 3);
    let (w, h) = (300u32, 260u32);
    let image = render_polygons(&set, &opts(View::Iso, w, h)).unwrap();
    let mut shade_of: std::collections::BTreeMap<i64, [u8; 3]> = Default::default();
    let mut checked = 0;
    // Probe pixel centres far from edges: map back through the frame.
    let [lo, hi] = set.bounding_box().unwrap();
    let m = margin(w, h);
    let scale = ((f64::from(w) - 2.0 * m) / (hi[0] - lo[0]))
        .min((f64::from(h) - 2.0 * m) / (hi[1] - lo[1]));
    let cx = (lo[0] + hi[0]) / 2.0;
    let cy = (lo[1] + hi[1]) / 2.0;
    for y in (0..h).step_by(3) {
        for x in (0..w).step_by(3) {
            let p = [
                cx + (f64::from(x) + 0.5 - f64::from(w) / 2.0) / scale,
                cy - (f64::from(y) + 0.5 - f64::from(h) / 2.0) / scale,
            ];
            // Keep away from edges (lines are drawn over the shade).
            let near = set.edges().iter().any(|e| {
                let (a, b) = set.edge_points(e);
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let t = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy))
                    .clamp(0.0, 1.0);
                let (qx, qy) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
                (qx * qx + qy * qy).sqrt() * scale < 4.0
            });
            if near {
                continue;
            }
            let wn = winding(&set, p);
            let c = image.pixel(x, y).unwrap();
            assert_eq!(
                *shade_of.entry(wn).or_insert(c),
                c,
                "winding {wn} at ({x}, {y})"
            );
            checked += 1;
        }
    }
    assert!(checked > 1000);
    // Windings 0, 1, 2, -1 and 3 all seen, in distinct shades.
    let keys: Vec<i64> = shade_of.keys().copied().collect();
    assert_eq!(keys, vec![-1, 0, 1, 2, 3]);
    let distinct: std::collections::BTreeSet<[u8; 3]> = shade_of.values().copied().collect();
    assert_eq!(distinct.len(), 5);
    assert_eq!(shade_of[&0], WHITE);
}

#[test]
fn aspect_ratio_is_true_in_2d() {
    // A 4 x 1 rectangle in a square frame: its filled pixels form a 4:1
    // rectangle as wide as the frame less the margins.
    let mut set = PolygonSet2::new();
    set.add_loop(&[[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 1.0]]);
    let image = render_polygons(&set, &opts(View::Iso, 200, 200)).unwrap();
    let (mut x0, mut x1, mut y0, mut y1) = (u32::MAX, 0, u32::MAX, 0);
    for y in 0..200 {
        for x in 0..200 {
            if image.pixel(x, y) != Some(WHITE) {
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            }
        }
    }
    let (wide, high) = (f64::from(x1 - x0 + 1), f64::from(y1 - y0 + 1));
    assert!((wide - 176.0).abs() <= 3.0, "{wide}");
    assert!((wide / high - 4.0).abs() < 0.3, "{wide} x {high}");
}

#[test]
fn topology_style_draws_one_arrowhead_per_unit_of_multiplicity() {
    // One triangle of multiplicity k: the dark pixels grow with k by
    // about the area of 3 arrowheads per unit.
    let dark = |k: i32| {
        let mut s = PolygonSet2::new();
        let a = s.add_vertex([0.0, 0.0]);
        let b = s.add_vertex([10.0, 0.0]);
        let c = s.add_vertex([5.0, 8.0]);
        for (p, q) in [(a, b), (b, c), (c, a)] {
            s.add_edge_mult(p, q, k);
        }
        let o = RenderOptions {
            style: Style::Topology,
            ..opts(View::Iso, 400, 400)
        };
        pixels(&render_polygons(&s, &o).unwrap())
            .filter(|c| c.iter().all(|&x| x < 60))
            .count()
    };
    let (d1, d2, d3) = (dark(1), dark(2), dark(3));
    assert!(d2 > d1 && d3 > d2, "{d1} {d2} {d3}");
    let (g1, g2) = (d2 - d1, d3 - d2);
    assert!(
        (g1 as f64 - g2 as f64).abs() <= 0.2 * g1 as f64,
        "{g1} {g2}"
    );
    // A huge multiplicity draws a bounded number of arrowheads, quickly.
    assert!(dark(i32::MAX) < 10 * d1);
}

#[test]
fn svg_is_well_formed_and_uses_numbers_only() {
    let o = RenderOptions {
        style: Style::Topology,
        ..opts(View::Iso, 300, 200)
    };
    let docs = [
        render_mesh_svg(&cuboid(1.0, 2.0, 3.0), &o).unwrap(),
        render_polygons_svg(&figure_eight(), &o).unwrap(),
        render_polygons_svg(&figure_eight(), &RenderOptions::default()).unwrap(),
    ];
    for doc in &docs {
        let xml = roxmltree::Document::parse(doc).unwrap();
        let root = xml.root_element();
        assert_eq!(root.tag_name().name(), "svg");
        assert!(root.children().filter(|n| n.is_element()).count() > 3);
        for n in xml.descendants().filter(|n| n.is_element()) {
            for a in n.attributes() {
                let v = a.value();
                assert!(
                    v.chars()
                        .all(|c| c.is_ascii_alphanumeric() || " .,-#:/".contains(c)),
                    "{}={v}",
                    a.name()
                );
            }
        }
    }
    // The 3D SVG paints the six faces back to front: the three far ones
    // first.
    let xml = roxmltree::Document::parse(&docs[0]).unwrap();
    assert_eq!(
        xml.descendants().filter(|n| n.has_tag_name("path")).count(),
        6
    );
    // The winding shades of the figure eight: both lobes in rectangles.
    assert!(docs[2].contains("<rect") && docs[2].matches("<rect").count() > 2);
}

mod garbage {
    //! Random and garbage shapes: a picture or an error, never a panic,
    //! and the same picture twice.
    use super::*;
    use proptest::prelude::*;

    fn coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![
            -10.0..10.0f64,
            Just(0.0),
            Just(f64::MAX / 4.0),
            Just(-f64::MAX / 4.0),
            Just(1e-300),
            Just(f64::NAN),
            Just(f64::INFINITY),
        ]
    }

    fn size() -> impl Strategy<Value = (u32, u32)> {
        prop_oneof![(1u32..64, 1u32..64), Just((0, 5)), Just((20_000, 3))]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(96)))]

        #[test]
        fn meshes_never_panic(
            vertices in proptest::collection::vec([coordinate(), coordinate(), coordinate()], 0..12),
            facets in proptest::collection::vec(proptest::collection::vec(0u32..14, 0..6), 0..8),
            (width, height) in size(),
            highlight in any::<bool>(),
            view in prop_oneof![Just(View::Iso), Just(View::Front), Just(View::Top), Just(View::Side)],
            topology in any::<bool>(),
        ) {
            let mesh = PolygonMesh::new(vertices, facets.iter().map(|l| Facet::from_loop(l)).collect());
            let o = RenderOptions {
                view,
                width,
                height,
                style: if topology { Style::Topology } else { Style::Filled },
                highlight,
            };
            let first = render_mesh(&mesh, &o);
            prop_assert_eq!(format!("{first:?}"), format!("{:?}", render_mesh(&mesh, &o)));
            if let Ok(image) = first {
                prop_assert_eq!((image.width(), image.height()), (width, height));
                prop_assert!(image.to_png().is_ok());
            }
            if let Ok(svg) = render_mesh_svg(&mesh, &o) {
                prop_assert!(roxmltree::Document::parse(&svg).is_ok());
            }
        }

        #[test]
        fn polygon_sets_never_panic(
            points in proptest::collection::vec([coordinate(), coordinate()], 0..10),
            edges in proptest::collection::vec((0u32..12, 0u32..12, prop_oneof![-3i32..4, Just(i32::MAX), Just(i32::MIN)]), 0..12),
            (width, height) in size(),
            topology in any::<bool>(),
        ) {
            let mut set = PolygonSet2::new();
            for p in &points {
                set.add_vertex(*p);
            }
            for &(a, b, m) in &edges {
                set.add_edge_mult(a, b, m);
            }
            let o = RenderOptions {
                width,
                height,
                style: if topology { Style::Topology } else { Style::Filled },
                ..RenderOptions::default()
            };
            let first = render_polygons(&set, &o);
            prop_assert_eq!(format!("{first:?}"), format!("{:?}", render_polygons(&set, &o)));
            if let Ok(svg) = render_polygons_svg(&set, &o) {
                prop_assert!(roxmltree::Document::parse(&svg).is_ok());
            }
        }
    }
}
