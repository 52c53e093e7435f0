//! The integration tests of `smooth`, one module per former test file, in
//! one test binary: each binary links the whole stack, so one per crate
//! instead of one per file saves most of the test build's link time.

mod mesh_common;
mod planar_support;

mod mesh_bad_input;
mod mesh_big_facets;
mod mesh_chain;
mod mesh_clusters;
mod mesh_difference;
mod mesh_figure_a1;
mod mesh_huge_coordinates;
mod mesh_near;
mod mesh_proptest;
mod mesh_real;
mod mesh_rotated;
mod mesh_stacked;
mod planar_cases;
mod planar_checker;
mod planar_errors;
mod planar_map;
mod planar_near;
mod planar_properties;
mod planar_scale;
