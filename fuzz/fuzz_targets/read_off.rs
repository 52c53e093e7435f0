//! Fuzz target: the OFF reader on any UTF-8 text never panics; a mesh that
//! reads is checked for closure (the linear `check_topology`: the
//! self-intersection check, which is quadratic in memory on large facets,
//! is exercised by the `parse` target), written in every mesh format to a
//! sink, and (when every facet is a simple loop) written as OFF and read
//! back to the same mesh bit for bit.
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{mesh_to_off, parse_off};
#[path = "common/io.rs"]
mod io;
use io::write_mesh_everywhere;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(mesh) = parse_off(text, "fuzz.off") else {
        return;
    };
    let _ = mesh.check_topology();
    if write_mesh_everywhere(&mesh) {
        let back = parse_off(&mesh_to_off(&mesh), "back.off").expect("written OFF reads back");
        assert_eq!(format!("{back:?}"), format!("{mesh:?}"), "OFF round trip");
    }
});
