//! `peak-memory-3d PEER TRIANGLES`: the heap peak of one 3D Boolean (sphere
//! minus shifted sphere, `umbra_benches::solid`), counted by a global
//! allocator (`peak_alloc`): the largest number of bytes live at once during
//! `A - B`, minus the bytes live before it (the prepared inputs). Prints
//! `peak_bytes output_facets`. Used by `perf-table-3d` for its memory
//! columns; a separate binary because the counting allocator slows zeroed
//! allocations, so timings are taken without it.

use peak_alloc::PeakAlloc;
use umbra_benches::solid::{
    sphere_pair, Boolmesh, ManifoldRust, SolidPeer, UmbraPolygons, UmbraQuads, UmbraTriangles,
};

#[global_allocator]
static PEAK: PeakAlloc = PeakAlloc;

fn measure<P: SolidPeer>(peer: &P, size: usize) {
    let (a, b) = sphere_pair(size);
    let input = peer.prepare(&a, &b);
    drop((a, b));
    let before = PEAK.current_usage();
    PEAK.reset_peak_usage();
    let out = peer.difference(&input);
    let peak = PEAK.peak_usage().saturating_sub(before);
    println!("{peak} {}", peer.stats(&out).facets);
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(peer), Some(size)) = (args.first(), args.get(1).and_then(|s| s.parse().ok())) else {
        eprintln!("usage: peak-memory-3d umbra-tri|umbra-poly|umbra-quads|manifold-rust|boolmesh TRIANGLES");
        std::process::exit(2);
    };
    match peer.as_str() {
        "umbra-tri" => measure(&UmbraTriangles, size),
        "umbra-poly" => measure(&UmbraPolygons, size),
        "umbra-quads" => measure(&UmbraQuads, size),
        "manifold-rust" => measure(&ManifoldRust, size),
        "boolmesh" => measure(&Boolmesh, size),
        other => {
            eprintln!("unknown peer {other}");
            std::process::exit(2);
        }
    }
}
