//! The inconsistent example of section 7.2 (figure 7.4): points A-G with
//! `u = 2^-53`, whose computed vertex-edge shadow relationships (Table 7.1
//! via `shadow_1d`) and edge-edge crossings (Table 7.2 via `shadow_2d::x11`)
//! are impossible in exact geometry. Every relationship the dissertation
//! lists is reproduced here, with exact f64 equality where it gives exact
//! values. The exact orientation of each triple is checked too, to show
//! which computed relationships contradict exact geometry.

use crate::common::U;
use shadow_1d::{s01, s10, x01, x10};
use shadow_2d::x11;
use test_support::exact::orient;

type P = [f64; 2];

const A: P = [0.5 + 9.0 * U, 0.5 + 23.0 * U];
const B: P = [0.5 + 23.0 * U, 0.5 + 25.0 * U];
const C: P = [9.0, 0.5];
const D: P = [9.0, 9.0];
const E: P = [9.0, 32.0];
const F: P = [32.0, 32.0 - 32.0 * U];
const G: P = [32.0, 32.0];

/// The roles-swapped decision: `S10(e_A, v_B)` with the edge as A, or
/// `None` when `X10` is zero (its x-interval is `[min, max)`, that of `X01`
/// `(min, max]`, so a vertex at the right end is only seen by `X01`).
fn vertex_shadows_edge(v: P, s: P, e: P) -> Option<bool> {
    x10(&s, &e, &v).map(|h| s10(&s, &e, &v) == h.value)
}

/// "v lies below edge s->e" as computed: the vertex is within the edge in
/// x (`X01 != 0`) and the edge shadows it (`S01 = X01`, eq. 4.1) strictly
/// (the edge's computed y is above the vertex, so no tie is involved).
fn below(v: P, s: P, e: P) -> bool {
    let h = x01(&v, &s, &e).expect("vertex within the edge in x");
    let edge_shadows = s01(&v, &s, &e) == h.value;
    if let Some(vs) = vertex_shadows_edge(v, s, e) {
        assert_eq!(vs, !edge_shadows, "S01 and S10 disagree off a tie");
    }
    edge_shadows && h.b[1] > v[1]
}

/// "v lies above edge s->e" as computed.
fn above(v: P, s: P, e: P) -> bool {
    let h = x01(&v, &s, &e).expect("vertex within the edge in x");
    let edge_shadows = s01(&v, &s, &e) == h.value;
    if let Some(vs) = vertex_shadows_edge(v, s, e) {
        assert_eq!(vs, !edge_shadows, "S01 and S10 disagree off a tie");
    }
    !edge_shadows && h.b[1] < v[1]
}

#[test]
fn the_points_are_as_printed() {
    assert_eq!(format!("{:.17}", A[0]), "0.50000000000000100");
    assert_eq!(format!("{:.16}", A[1]), "0.5000000000000026");
    assert_eq!(format!("{:.16}", F[1]), "31.9999999999999964");
    const { assert!(A[0] < B[0] && B[0] < C[0]) };
}

#[test]
fn vertex_edge_shadows_of_section_7_2() {
    // B lies below both AF and AG.
    assert!(below(B, A, F), "B below AF");
    assert!(below(B, A, G), "B below AG");
    // F lies below both AG and BG.
    assert!(below(F, A, G), "F below AG");
    assert!(below(F, B, G), "F below BG");
    // D lies above both AF and AG.
    assert!(above(D, A, F), "D above AF");
    assert!(above(D, A, G), "D above AG");
    // D lies below both BF and BG.
    assert!(below(D, B, F), "D below BF");
    assert!(below(D, B, G), "D below BG");
    // Reversing the half-edge negates the functions, same decision.
    assert_eq!(s01(&D, &F, &B), -1);
    assert_eq!(s01(&D, &F, &A), 0);
}

#[test]
fn exact_geometry_contradicts_some_computed_shadows() {
    // Exact orientation: positive when v is left of s->e, i.e. above an
    // edge going left to right.
    let exactly_above = |v: P, s: P, e: P| orient(s, e, v) > 0;
    // Computed "D above AF and AG": exactly, D is below both.
    assert!(above(D, A, F) && !exactly_above(D, A, F));
    assert!(above(D, A, G) && !exactly_above(D, A, G));
    // Computed "D below BF": exactly, D is above BF.
    assert!(below(D, B, F) && exactly_above(D, B, F));
    // The other listed relationships agree with exact geometry.
    for (v, s, e) in [(B, A, F), (B, A, G), (F, A, G), (F, B, G), (D, B, G)] {
        assert!(below(v, s, e) && orient(s, e, v) < 0);
    }
    // The computed set is impossible: BF lies below AG (B and F are both
    // computed below AG), yet D is computed above AG and below BF.
    assert!(below(B, A, G) && below(F, A, G) && above(D, A, G) && below(D, B, F));
}

#[test]
fn edge_edge_crossings_of_section_7_2() {
    let cross = |s: P, e: P, s2: P, e2: P| {
        x11(&s, &e, &s2, &e2)
            .expect("Theorem 1: partners exist")
            .expect("the edges cross")
    };
    let below_9 = [9.0, 9.0 - 16.0 * U];
    let above_9 = [9.0, 9.0 + 16.0 * U];
    assert_eq!(format!("{:.17}", below_9[1]), "8.99999999999999822");
    assert_eq!(format!("{:.17}", above_9[1]), "9.00000000000000178");
    // Both AF and AG cross CE left to right at (9, 9 - 16u).
    for end in [F, G] {
        let h = cross(A, end, C, E);
        assert_eq!(h.value, 1, "A{end:?} crosses CE left to right");
        assert_eq!(h.a, below_9, "A{end:?} x CE");
        assert_eq!(h.b, below_9);
        // Reversing CE negates the value, same point.
        let r = cross(A, end, E, C);
        assert_eq!((r.value, r.a), (-1, below_9));
    }
    // Both BF and BG cross CE left to right at (9, 9 + 16u).
    for end in [F, G] {
        let h = cross(B, end, C, E);
        assert_eq!(h.value, 1, "B{end:?} crosses CE left to right");
        assert_eq!(h.a, above_9, "B{end:?} x CE");
    }
    // AF crosses BG left to right at (9.09090909090909172, 9.09090909090909172).
    let h = cross(A, F, B, G);
    assert_eq!(h.value, 1, "AF crosses BG left to right");
    assert_eq!(format!("{:.15}", h.a[0]), "9.090909090909092");
    assert_eq!(h.a, [9.090_909_090_909_092, 9.090_909_090_909_092]);
    assert_eq!(h.a[0], h.a[1]);
    // So AF, BG and CE do not form a valid cell structure: AF crosses CE
    // below BG does (9 - 16u < 9 + 16u) and yet crosses BG to the right of
    // CE (x = 9.0909... > 9), which needs AF to pass above BG at x = 9.
    assert!(h.a[0] > 9.0);
}
