//! The demo scene: a small process-plant skid as a CSG tree of some
//! hundreds of Booleans (vessels with hemispherical and dished heads,
//! pipe runs with elbows and bolted flanges, a pump, a pipe rack and a
//! base frame with bolted base plates). Units are metres, z is up.
//!
//! Parts that join overlap by a small positive amount (a column stands
//! 1 cm deep in its base plate, a pipe end sinks into the vessel it
//! feeds, a pipe runs 1 cm into its elbow) and no two parts share a face,
//! an edge or a tangent: until the smoothing pass exists the basic
//! Boolean resolves such coincidences by symbolic perturbation, which is
//! topologically valid but leaves zero-thickness sheets and slivers.
//! Coaxial round parts are nested (a head slightly inside its shell, an
//! elbow slightly fatter than its pipe), and round parts whose edges would
//! otherwise meet the edges of a neighbour exactly are turned by half a
//! segment about their axis (or, for a pipe entering a head on its axis,
//! moved off that axis).

use super::transform::Transform;
use super::tree::CsgNode;
use glam::{DMat3, DVec3};

/// The resolution of the demo scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DemoDetail {
    /// The full scene (96 segments on vessels, 32 on pipes).
    #[default]
    Full,
    /// The same scene with a sixth to a quarter of the segments (for quick
    /// tests).
    Coarse,
}

/// Segment counts of one detail level.
#[derive(Clone, Copy)]
struct Res {
    vessel: u32,
    pipe: u32,
    bolt: u32,
    ring: u32,
}

impl DemoDetail {
    fn res(self) -> Res {
        match self {
            DemoDetail::Full => Res {
                vessel: 96,
                pipe: 32,
                bolt: 12,
                ring: 12,
            },
            DemoDetail::Coarse => Res {
                vessel: 16,
                pipe: 8,
                bolt: 4,
                ring: 4,
            },
        }
    }
}

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// Rotation angles (multiples of 90 degrees, about x then y then z) whose
/// matrix is exactly `target` (an axis permutation with signs).
fn axis_angles(target: DMat3) -> [f64; 3] {
    const Q: [f64; 4] = [0.0, 90.0, 180.0, 270.0];
    for a in Q {
        for b in Q {
            for c in Q {
                let t = Transform {
                    rotate: Some([a, b, c]),
                    ..Transform::default()
                };
                if DMat3::from_mat4(t.matrix()) == target {
                    return [a, b, c];
                }
            }
        }
    }
    [0.0; 3]
}

/// The exact unit axis vector along the largest component of `v` (the
/// directions of the pipe runs are axis-aligned; dividing by the length
/// could be off by an ulp).
fn axis_dir(v: DVec3) -> DVec3 {
    let a = v.abs();
    if a.x >= a.y && a.x >= a.z {
        DVec3::X * v.x.signum()
    } else if a.y >= a.z {
        DVec3::Y * v.y.signum()
    } else {
        DVec3::Z * v.z.signum()
    }
}

/// A unit vector perpendicular to the axis-aligned unit vector `d`.
fn perpendicular(d: DVec3) -> DVec3 {
    if d.z.abs() == 1.0 {
        DVec3::X
    } else {
        DVec3::Z
    }
}

/// A leaf built along z, turned so that its z axis runs along the
/// axis-aligned direction `d`, then moved to `at`.
fn along(node: CsgNode, d: DVec3, at: DVec3) -> CsgNode {
    let x = perpendicular(d);
    let y = d.cross(x);
    node.rotated(axis_angles(DMat3::from_cols(x, y, d)))
        .translated(at.to_array())
}

/// A bolted flange: a disc of radius `2.2 r` and thickness `0.3 r`
/// centred at `at`, normal `d`, with eight bolt holes (the bore comes from
/// the pipe run).
fn flange(r: f64, d: DVec3, at: DVec3, res: Res) -> CsgNode {
    let t = 0.3 * r;
    // Not turned like the pipe: the pipe's edges then pierce the disc's
    // faces away from the diagonals through its corners.
    let disc = CsgNode::cylinder(2.2 * r, t, res.pipe, true);
    let mut parts = vec![disc];
    for k in 0..8 {
        let a = (f64::from(k) * 45.0 + 22.5).to_radians();
        let p = 1.7 * r;
        parts.push(
            CsgNode::cylinder(0.18 * r, 2.0 * t, res.bolt, true).translated([
                p * a.cos(),
                p * a.sin(),
                0.0,
            ]),
        );
    }
    along(CsgNode::difference(parts), d, at)
}

/// The node turned about z by half of one of its `segments`.
fn half_turned(node: CsgNode, segments: u32) -> CsgNode {
    node.rotated([0.0, 0.0, 180.0 / f64::from(segments)])
}

/// A quarter torus (tube radius `r`, bend radius `rb`) joining the
/// direction `d1` into `d2` at the corner `c`. Its ends lie `cut` past the
/// planes through `c - d1 rb` normal to `d1` and through `c + d2 rb`
/// normal to `d2` (where the torus has meridian edges), so that they cut
/// the torus's facets rather than hold its edges.
fn elbow_quarter(r: f64, rb: f64, d1: DVec3, d2: DVec3, c: DVec3, res: Res, cut: f64) -> CsgNode {
    let margin = 0.01;
    let e = rb + r + margin;
    let quadrant = CsgNode::cuboid([e + cut, e + cut, 2.0 * (r + margin)], false).translated([
        -cut,
        -cut,
        -(r + margin),
    ]);
    let ring = CsgNode::torus(rb, r, [4 * (res.pipe / 2).max(3), res.pipe]);
    let q = CsgNode::intersection(vec![ring, quadrant]);
    let x = d1;
    let y = -d2;
    let rot = axis_angles(DMat3::from_cols(x, y, x.cross(y)));
    let o = c - d1 * rb + d2 * rb;
    q.rotated(rot).translated(o.to_array())
}

/// The ratio of an elbow's tube radius to its pipe's (a socket-weld
/// fitting: the straight runs into the fatter elbow, so the two round
/// surfaces are nested, never tangent).
const ELBOW: f64 = 1.12;

/// How far a straight runs into its elbow.
const SOCKET: f64 = 0.01;

/// A hollow pipe along the axis-aligned polyline `points` (each corner a
/// right angle, each straight at least `2 rb` long between corners), with
/// socket elbows (tori of bend radius `rb`, tube `1.12 r`), outer radius
/// `r`, wall `0.2 r`, and bolted flanges 0.3 m from each end (halfway
/// along a shorter end straight) and in pairs (with a gasket gap) at the
/// middle of long straights.
fn pipe_run(points: &[DVec3], r: f64, rb: f64, res: Res) -> CsgNode {
    let ri = 0.8 * r;
    let n = points.len();
    let dir = |i: usize| axis_dir(points[i + 1] - points[i]);
    // A straight cylinder from `a` along `d`, turned by half a segment so
    // that its edges miss the edges of the shells it enters radially.
    let straight = |radius: f64, len: f64, d: DVec3, a: DVec3| {
        along(
            half_turned(CsgNode::cylinder(radius, len, res.pipe, false), res.pipe),
            d,
            a,
        )
    };
    let mut outer = Vec::new();
    let mut bores = Vec::new();
    for i in 0..n - 1 {
        let d = dir(i);
        let a = if i == 0 {
            points[0]
        } else {
            points[i] + d * rb
        };
        let b = if i == n - 2 {
            points[n - 1]
        } else {
            points[i + 1] - d * rb
        };
        let len = (b - a).length();
        // Into an elbow the straights run SOCKET deep; the end bores run
        // 5 mm past the pipe's open ends.
        let (out_a, bore_a) = if i == 0 {
            (0.0, 0.005)
        } else {
            (SOCKET, SOCKET)
        };
        let (out_b, bore_b) = if i == n - 2 {
            (0.0, 0.005)
        } else {
            (SOCKET, SOCKET)
        };
        outer.push(straight(r, len + out_a + out_b, d, a - d * out_a));
        bores.push(straight(ri, len + bore_a + bore_b, d, a - d * bore_a));
        // End flanges 0.3 m from the end, or halfway along a short
        // straight (clear of the elbow's end).
        let end_flange = (0.5 * len).min(0.3);
        if i == 0 {
            outer.push(flange(r, d, a + d * end_flange, res));
        }
        if i == n - 2 {
            outer.push(flange(r, d, b - d * end_flange, res));
        }
        if len > 3.0 {
            let mid = a + d * (len / 2.0);
            outer.push(flange(r, d, mid - d * (0.16 * r), res));
            outer.push(flange(r, d, mid + d * (0.16 * r), res));
        }
        if i + 2 < n {
            let d2 = dir(i + 1);
            let c = points[i + 1];
            outer.push(elbow_quarter(ELBOW * r, rb, d, d2, c, res, 0.004));
            bores.push(elbow_quarter(ELBOW * ri, rb, d, d2, c, res, 0.004));
        }
    }
    CsgNode::difference(vec![CsgNode::union(outer), CsgNode::union(bores)])
}

/// The height of the base plates' undersides: 8 mm deep in the deck
/// (whose top is at 0.3), above the beams under it.
const PLATE_Z: f64 = 0.292;

/// The height from which parts standing on a base plate start (1.2 cm
/// deep in the plate, whose top is at 0.322).
const ON_PLATE: f64 = 0.31;

/// A base plate `w x w x t` centred at `(x, y)` from `z` up, with four bolt
/// holes.
fn base_plate(x: f64, y: f64, z: f64, w: f64, res: Res) -> CsgNode {
    let t = 0.03;
    let mut parts = vec![CsgNode::cuboid([w, w, t], false).translated([-w / 2.0, -w / 2.0, 0.0])];
    let o = w / 2.0 - 0.06;
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        parts.push(
            CsgNode::cylinder(0.015, 3.0 * t, res.bolt, true).translated([sx * o, sy * o, t / 2.0]),
        );
    }
    CsgNode::difference(parts).translated([x, y, z])
}

/// An axis-aligned box between two corners.
fn block(lo: DVec3, hi: DVec3) -> CsgNode {
    CsgNode::cuboid((hi - lo).to_array(), false).translated(lo.to_array())
}

/// The skid: a deck plate `[0, 14] x [-3, 3] x [0.27, 0.3]` on two main
/// beams along x (1 cm inside the deck's edges, their tops 2 cm up in the
/// deck) and five cross beams (running 5 cm into the main beams, from
/// 1 cm above their undersides to 1.5 cm up in the deck).
fn skid() -> CsgNode {
    let mut parts = vec![
        block(v(0.0, -3.0, 0.27), v(14.0, 3.0, 0.3)),
        block(v(0.01, -2.99, 0.0), v(13.99, -2.7, 0.29)),
        block(v(0.01, 2.7, 0.0), v(13.99, 2.99, 0.29)),
    ];
    for x in [0.02, 3.4, 6.9, 10.3, 13.68] {
        parts.push(block(v(x, -2.75, 0.01), v(x + 0.3, 2.75, 0.285)));
    }
    CsgNode::union(parts)
}

/// A portal frame of the pipe rack at `x`: two columns on bolted base
/// plates and beams at the given heights (their tops; the columns stand
/// 2 cm above the top beam, the beams end 5 cm inside the columns).
fn portal(x: f64, beams: &[f64], top: f64, res: Res) -> CsgNode {
    let mut parts = Vec::new();
    for y in [-2.84, 2.84] {
        parts.push(block(
            v(x - 0.1, y - 0.1, ON_PLATE),
            v(x + 0.1, y + 0.1, top + 0.02),
        ));
        parts.push(base_plate(x, y, PLATE_Z, 0.3, res));
    }
    for &z in beams {
        parts.push(block(v(x - 0.08, -2.89, z - 0.16), v(x + 0.08, 2.89, z)));
    }
    CsgNode::union(parts)
}

/// How much smaller a head's radius is than its shell's: the head is
/// nested inside the shell where they overlap, never tangent to it.
const HEAD_INSET: f64 = 0.005;

/// A vertical vessel on a skirt: shell radius `r` from `z0` to `z1`, a
/// hemispherical top head (sphere ∩ box, its centre 2 cm down in the
/// shell), a dished bottom head (a sphere of crown radius `1.6 r` ∩ a
/// cylinder) hidden in the skirt, stiffener rings (tori biting 2.5 cm into
/// the shell) and a manway with a bolted blind flange.
fn vertical_vessel(x: f64, y: f64, r: f64, z0: f64, z1: f64, res: Res) -> CsgNode {
    let s = res.vessel;
    let shell = CsgNode::cylinder(r, z1 - z0, s, false).translated([x, y, z0]);
    let top = CsgNode::intersection(vec![
        CsgNode::sphere(r - HEAD_INSET, s).translated([x, y, z1 - 0.02]),
        block(
            v(x - r - 0.1, y - r - 0.1, z1 - 0.01),
            v(x + r + 0.1, y + r + 0.1, z1 + r + 0.1),
        ),
    ]);
    let rc = 1.6 * r;
    let depth = rc - (rc * rc - r * r).sqrt();
    // The dish's sphere is turned by half a segment: it crosses the
    // trimming cylinder and the skirt's inside, whose meridian edges would
    // otherwise meet its own.
    let bottom = CsgNode::intersection(vec![
        half_turned(CsgNode::sphere(rc, s), s).translated([x, y, z0 - depth + rc]),
        CsgNode::cylinder(r - 0.03, depth + 0.05, s, false).translated([x, y, z0 - depth - 0.01]),
    ]);
    // The skirt stands 5 mm deep in the deck and runs 3 cm up into the
    // shell, 4 mm inside its surface.
    let skirt = CsgNode::difference(vec![
        CsgNode::cylinder(r - 0.004, z0 + 0.03 - 0.295, s, false).translated([x, y, 0.295]),
        CsgNode::cylinder(r - 0.06, z0 - 0.15, s, false).translated([x, y, 0.25]),
        // Two access openings.
        block(
            v(x - 0.25, y - r - 0.1, 0.45),
            v(x + 0.25, y + r + 0.1, 0.45 + 0.5),
        ),
    ]);
    let mut parts = vec![shell, top, bottom, skirt];
    let mut z = z0 + 1.2;
    while z < z1 - 0.5 {
        parts.push(
            half_turned(CsgNode::torus(r + 0.015, 0.04, [s, res.ring]), s).translated([x, y, z]),
        );
        z += 1.5;
    }
    // Manway on the -x side below the first ring: a stub (10 cm deep in the
    // shell) and a blind flange (the stub 1 cm deep in it) with twelve bolt
    // heads (1 cm deep in it).
    let mz = z0 + 0.7;
    let stub = along(
        half_turned(CsgNode::cylinder(0.3, 0.44, res.pipe, false), res.pipe),
        -DVec3::X,
        v(x - r + 0.1, y, mz),
    );
    let mut blind = vec![CsgNode::cylinder(0.42, 0.06, res.pipe, false)];
    for k in 0..12 {
        let a = (f64::from(k) * 30.0).to_radians();
        blind.push(CsgNode::cylinder(0.025, 0.09, res.bolt, false).translated([
            0.36 * a.cos(),
            0.36 * a.sin(),
            0.01,
        ]));
    }
    parts.push(stub);
    parts.push(along(
        CsgNode::union(blind),
        -DVec3::X,
        v(x - r - 0.33, y, mz),
    ));
    CsgNode::union(parts)
}

/// A horizontal drum along x on two saddles: shell radius `r` from `x0`
/// to `x1` at `(y, z)`, hemispherical heads (sphere ∩ box, their centres
/// 2 cm inside the shell, their axes along the shell's).
fn drum(x0: f64, x1: f64, y: f64, z: f64, r: f64, res: Res) -> CsgNode {
    let s = res.vessel;
    let shell = along(
        CsgNode::cylinder(r, x1 - x0, s, false),
        DVec3::X,
        v(x0, y, z),
    );
    let head = |xc: f64, lo: f64, hi: f64| {
        CsgNode::intersection(vec![
            along(CsgNode::sphere(r - HEAD_INSET, s), DVec3::X, v(xc, y, z)),
            block(
                v(lo, y - r - 0.1, z - r - 0.1),
                v(hi, y + r + 0.1, z + r + 0.1),
            ),
        ])
    };
    let mut parts = vec![
        shell,
        head(x0 + 0.02, x0 - r - 0.1, x0 + 0.01),
        head(x1 - 0.02, x1 - 0.01, x1 + r + 0.1),
    ];
    for xs in [x0 + 0.6, x1 - 0.6] {
        // The saddle's cradle is 2 cm smaller than the shell, so the shell
        // sits 2 cm deep in it.
        let saddle = CsgNode::difference(vec![
            block(
                v(xs - 0.15, y - 0.8 * r, ON_PLATE),
                v(xs + 0.15, y + 0.8 * r, z),
            ),
            along(
                CsgNode::cylinder(r - 0.02, 0.5, s, false),
                DVec3::X,
                v(xs - 0.25, y, z),
            ),
        ]);
        parts.push(saddle);
        parts.push(base_plate(xs, y, PLATE_Z, 0.5, res));
    }
    CsgNode::union(parts)
}

/// A pump: casing, motor and fan cover on a bolted base plate, each part
/// 2 cm deep in the one below and a little narrower.
fn pump(x: f64, y: f64, res: Res) -> CsgNode {
    CsgNode::union(vec![
        base_plate(x, y, PLATE_Z, 0.8, res),
        CsgNode::cylinder(0.35, 0.92, res.pipe, false).translated([x, y, ON_PLATE]),
        CsgNode::cylinder(0.25, 0.77, res.pipe, false).translated([x, y, 1.21]),
        CsgNode::cone(0.24, 0.1, 0.17, res.pipe, false).translated([x, y, 1.96]),
    ])
}

/// The demo process-plant skid as a CSG tree: a vertical vessel, a
/// distillation column with a platform, a horizontal drum on saddles, a
/// pump, a pipe rack of two portal frames, a base frame, and six pipe runs
/// with elbows and bolted flanges. [`DemoDetail::Full`] runs some hundreds
/// of Booleans; [`DemoDetail::Coarse`] is the same tree with fewer
/// segments.
///
/// ```
/// use umbra::{demo_plant, evaluate_csg, CsgOptions, DemoDetail};
///
/// let tree = demo_plant(DemoDetail::Coarse);
/// assert!(tree.boolean_count() > 300);
/// let out = evaluate_csg(&tree, CsgOptions::default())?;
/// assert!(out.report.topologically_valid && out.report.volume > 0.0);
/// # Ok::<(), umbra::ModelError>(())
/// ```
pub fn demo_plant(detail: DemoDetail) -> CsgNode {
    CsgNode::union(plant_parts(detail))
}

/// The parts of the plant (the children of its root union).
fn plant_parts(detail: DemoDetail) -> Vec<CsgNode> {
    let res = detail.res();
    let platform = CsgNode::difference(vec![
        block(v(5.8, 0.0, 5.9), v(8.2, 2.4, 6.0)),
        // The column (radius 0.7) runs through the platform.
        CsgNode::cylinder(0.68, 0.3, res.vessel, false).translated([7.0, 1.2, 5.8]),
    ]);
    let r = 0.12;
    let rb = 0.4;
    let runs = [
        // Vessel top outlet over the rack into the column.
        vec![
            // (Its open end 4.5 cm deep in the head, clear of the head's
            // rings of vertices at either detail, and 3 cm off the head's
            // axis so that its edges miss the head's meridians.)
            v(2.5, 0.03, 5.93),
            v(2.5, 0.03, 6.8),
            v(5.0, 0.03, 6.8),
            v(5.0, 1.2, 6.8),
            v(6.4, 1.2, 6.8),
        ],
        // Vessel side outlet to the drum's head.
        vec![
            v(3.4, 0.0, 2.0),
            v(5.2, 0.0, 2.0),
            v(5.2, -1.5, 2.0),
            v(8.9, -1.5, 2.0),
        ],
        // Column side outlet into the drum's top.
        vec![
            v(7.0, 0.6, 3.4),
            v(7.0, -0.4, 3.4),
            v(11.2, -0.4, 3.4),
            v(11.2, -1.5, 3.4),
            v(11.2, -1.5, 2.7),
        ],
        // Drum bottom outlet to the pump's suction.
        vec![v(11.8, -1.5, 1.3), v(11.8, -1.5, 0.6), v(11.8, 1.0, 0.6)],
        // Pump discharge up and back into the column.
        vec![
            v(12.1, 1.2, 0.9),
            v(13.0, 1.2, 0.9),
            v(13.0, 1.2, 4.5),
            v(7.6, 1.2, 4.5),
        ],
        // Column overhead vapour line with a flanged end.
        vec![
            v(7.0, 1.2, 8.8),
            v(7.0, 1.2, 9.5),
            v(4.0, 1.2, 9.5),
            v(4.0, 1.2, 8.0),
        ],
    ];
    let mut parts = vec![
        skid(),
        portal(4.2, &[1.76, 6.56], 6.56, res),
        portal(8.2, &[1.76, 3.16, 4.26], 4.26, res),
        vertical_vessel(2.5, 0.0, 1.0, 1.5, 5.0, res),
        vertical_vessel(7.0, 1.2, 0.7, 1.3, 8.3, res),
        platform,
        drum(9.5, 13.0, -1.5, 2.0, 0.8, res),
        pump(11.8, 1.2, res),
    ];
    for run in &runs {
        parts.push(pipe_run(run, r, rb, res));
    }
    parts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_axis_rotation_has_exact_angles() {
        let axes = [
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            -DVec3::X,
            -DVec3::Y,
            -DVec3::Z,
        ];
        let mut found = 0;
        for x in axes {
            for y in axes {
                if x.dot(y) != 0.0 {
                    continue;
                }
                let target = DMat3::from_cols(x, y, x.cross(y));
                let t = Transform {
                    rotate: Some(axis_angles(target)),
                    ..Transform::default()
                };
                assert_eq!(DMat3::from_mat4(t.matrix()), target);
                found += 1;
            }
        }
        assert_eq!(found, 24);
        assert_eq!(axis_dir(DVec3::new(0.0, -1.5, 0.0)), -DVec3::Y);
    }

    #[test]
    fn pipe_runs_follow_their_polylines() {
        // Every straight of every run lies within the run's bounding box.
        let tree = demo_plant(DemoDetail::Coarse);
        let json = tree.to_json_string();
        assert!(json.len() > 10_000);
        let res = DemoDetail::Coarse.res();
        let points = [v(0.0, 0.0, 1.0), v(0.0, 2.0, 1.0), v(3.0, 2.0, 1.0)];
        let run = pipe_run(&points, 0.1, 0.4, res);
        let out = crate::evaluate_csg(&run, crate::CsgOptions::default()).unwrap();
        let b = out.report.bounds.unwrap();
        let r = 2.2 * 0.1; // the flanges' radius
        for k in 0..3 {
            let lo = points.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
            let hi = points
                .iter()
                .map(|p| p[k])
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                b[0][k] >= lo - r - 1e-9 && b[1][k] <= hi + r + 1e-9,
                "axis {k}: {b:?}"
            );
        }
        assert!(out.report.topologically_valid && out.report.volume > 0.0);
    }
}
