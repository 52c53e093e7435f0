//! Fuzz target: the PLY reader on any bytes never panics; a mesh that reads
//! is checked for closure (the linear `check_topology`: the
//! self-intersection check, which is quadratic in memory on large facets,
//! is exercised by the `parse` target), written in every mesh format to a
//! sink, and (when every facet is a simple loop) written as binary and
//! ASCII PLY and read back to the same mesh bit for bit.
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{mesh_to_ply, parse_ply};
#[path = "common/io.rs"]
mod io;
use io::write_mesh_everywhere;

fuzz_target!(|data: &[u8]| {
    let Ok(mesh) = parse_ply(data, "fuzz.ply") else {
        return;
    };
    let _ = mesh.check_topology();
    if write_mesh_everywhere(&mesh) {
        for ascii in [false, true] {
            let back =
                parse_ply(&mesh_to_ply(&mesh, ascii), "back.ply").expect("written PLY reads back");
            assert_eq!(format!("{back:?}"), format!("{mesh:?}"), "PLY round trip");
        }
    }
});
