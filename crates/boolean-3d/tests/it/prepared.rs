//! Prepared operands (`PreparedTriangles`, `boolean_prepared`) give the
//! one-call Boolean's result bit for bit: on random pairs of boxes,
//! icospheres and tetrahedra at different scales and offsets (so that
//! either operand's coordinate bound may be the larger and its broad phase
//! is built again), against small operands (where the one-call Boolean
//! scans boxes instead of building a hierarchy), with coplanar merges, for
//! every operation, and with one prepared operand reused across several
//! Booleans. Bad input is refused as the one-call Boolean refuses it.

use boolean_3d::{
    boolean_prepared, boolean_triangles, Boolean3Error, BooleanOp, Operand, PreparedTriangles,
};
use proptest::prelude::*;
use test_support::shapes::{box_triangles, icosphere, tetra};
use topology::{TopologyError, TriangleMesh};

#[derive(Clone, Debug)]
enum Shape {
    Box,
    Sphere(u32),
    Tetra,
}

fn shape(s: &Shape, centre: [f64; 3], size: f64) -> TriangleMesh {
    let [x, y, z] = centre;
    match s {
        Shape::Box => box_triangles(
            [x - size, y - size, z - size],
            [x + size, y + size, z + size],
        ),
        Shape::Sphere(levels) => icosphere(centre, size, *levels),
        Shape::Tetra => tetra([
            [x - size, y - size, z - size],
            [x + size, y - size, z - size],
            [x, y + size, z - size],
            [x, y, z + size],
        ]),
    }
}

fn shape_strategy() -> impl Strategy<Value = Shape> {
    prop_oneof![
        Just(Shape::Box),
        (0u32..4).prop_map(Shape::Sphere),
        Just(Shape::Tetra),
    ]
}

const OPS: [BooleanOp; 3] = [
    BooleanOp::Union,
    BooleanOp::Intersection,
    BooleanOp::Difference,
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(48)))]

    #[test]
    fn prepared_operands_give_the_one_call_result(
        sa in shape_strategy(),
        sb in shape_strategy(),
        offset in prop::array::uniform3(-1.5f64..1.5),
        size_b in 0.2f64..2.0,
        exp in -3i32..4,
    ) {
        // B's coordinates may be larger or smaller than A's by powers of two.
        let scale = 2f64.powi(exp);
        let a = shape(&sa, [0.0; 3], 1.0);
        let b = shape(&sb, offset.map(|c| c * scale), size_b * scale);
        let (pa, pb) = (PreparedTriangles::new(&a).unwrap(), PreparedTriangles::new(&b).unwrap());
        for op in OPS {
            let one_call = boolean_triangles(&a, &b, op);
            prop_assert_eq!(&boolean_prepared(&pa, &pb, op), &one_call, "{:?}", op);
            // The same prepared operands the other way round.
            prop_assert_eq!(boolean_prepared(&pb, &pa, op), boolean_triangles(&b, &a, op));
        }
    }
}

#[test]
fn one_prepared_operand_serves_many_booleans() {
    // A fine sphere against a series of small boxes (the one-call Boolean
    // scans the sphere's boxes against each box) and a larger sphere.
    let sphere = icosphere([0.0; 3], 1.0, 4);
    let prepared = PreparedTriangles::new(&sphere).unwrap();
    assert_eq!(prepared.mesh(), &sphere);
    for k in 0..6 {
        let x = -1.2 + 0.4 * f64::from(k);
        let tool = box_triangles([x, -0.1, -2.0], [x + 0.2, 0.1, 2.0]);
        let pt = PreparedTriangles::new(&tool).unwrap();
        for op in OPS {
            assert_eq!(
                boolean_prepared(&prepared, &pt, op),
                boolean_triangles(&sphere, &tool, op),
                "box {k} {op:?}"
            );
        }
    }
    let big = icosphere([0.5, 0.0, 0.0], 3.0, 2);
    let pbig = PreparedTriangles::new(&big).unwrap();
    for op in OPS {
        assert_eq!(
            boolean_prepared(&prepared, &pbig, op),
            boolean_triangles(&sphere, &big, op)
        );
    }
}

#[test]
fn bad_input_is_refused_like_the_one_call_boolean() {
    let a = box_triangles([0.0; 3], [1.0; 3]);
    // A dangling index.
    let mut dangling = a.clone();
    dangling.triangles[3][1] = 99;
    let err = PreparedTriangles::new(&dangling).unwrap_err();
    assert_eq!(
        Err(err),
        boolean_triangles(&dangling, &a, BooleanOp::Union).map(|_| ())
    );
    // Open topology: a missing triangle.
    let mut open = a.clone();
    open.triangles.pop();
    assert!(matches!(
        PreparedTriangles::new(&open),
        Err(Boolean3Error::InvalidInput {
            operand: Operand::A,
            source: TopologyError::ShapeClosure3 { .. }
        })
    ));
    // Not finite.
    let mut nan = a.clone();
    nan.vertices[2][0] = f64::NAN;
    assert!(matches!(
        PreparedTriangles::new(&nan),
        Err(Boolean3Error::InvalidInput { .. })
    ));
    // Xor is refused before any work, and nothing was changed.
    let p = PreparedTriangles::new(&a).unwrap();
    assert_eq!(
        boolean_prepared(&p, &p, BooleanOp::Xor),
        Err(Boolean3Error::UnsupportedOperation(BooleanOp::Xor))
    );
    assert_eq!(p.mesh(), &box_triangles([0.0; 3], [1.0; 3]));
}
