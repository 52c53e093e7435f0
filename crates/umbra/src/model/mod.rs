//! Modelling: primitives on `glam` ([`cuboid`], [`uv_sphere`],
//! [`icosphere`], [`cylinder`], [`torus`], [`regular_polygon`], [`circle`],
//! [`extrude`]), affine transforms as `DMat4` ([`transform_mesh`]), CSG
//! trees in a JSON form ([`CsgNode`], [`parse_csg`], [`read_csg_file`])
//! evaluated with the 3D Boolean ([`evaluate_csg`]), and a demo scene
//! ([`demo_plant`]).

mod clean;
mod demo;
mod error;
mod eval;
mod primitives;
mod transform;
mod tree;

pub use demo::{demo_plant, DemoDetail};
pub use error::ModelError;
pub use eval::{
    evaluate_csg, evaluate_csg_with_progress, CsgOptions, CsgReport, CsgResult, CsgTimings,
    NodeReport,
};
pub use glam::{DMat3, DMat4, DVec3};
pub use primitives::{
    circle, cuboid, cylinder, extrude, icosphere, regular_polygon, torus, uv_sphere,
    MAX_ICOSPHERE_LEVEL, MAX_PRIMITIVE_FACETS, MAX_SEGMENTS,
};
pub use transform::{transform_mesh, transform_triangles, Scale, Transform};
pub use tree::{
    parse_csg, parse_csg_value, read_csg_file, BoxSpec, CsgNode, CsgShape, CylinderSpec,
    SphereSpec, TorusSpec, DEFAULT_SEGMENTS, DEFAULT_TORUS_SEGMENTS, MAX_DEPTH,
};
