//! Fuzz target: the file readers (WKT, GeoJSON, OBJ, OFF) and the checks
//! never panic on any bytes; whatever parses is checked and, for 2D,
//! written back and read again.
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{
    check_mesh, check_polygon_set, parse_obj, parse_off, read_geojson_str, read_wkt_str,
    write_wkt_string, ReadOptions, RingOrientation,
};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    for options in [ReadOptions::default(), ReadOptions::keep_orientation()] {
        for set in [
            read_wkt_str(&text, options),
            read_geojson_str(&text, options),
        ]
        .into_iter()
        .flatten()
        {
            let _ = check_polygon_set(&set);
            if let Ok(out) = write_wkt_string(&set, RingOrientation::AsWritten) {
                read_wkt_str(&out, ReadOptions::keep_orientation())
                    .expect("written WKT reads back");
            }
        }
    }
    if let Ok(m) = parse_obj(&text, "fuzz.obj") {
        let _ = check_mesh(&m);
    }
    if let Ok(m) = parse_off(&text, "fuzz.off") {
        let _ = check_mesh(&m);
    }
});
