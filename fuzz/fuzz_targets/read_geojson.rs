//! Fuzz target: the GeoJSON reader on any UTF-8 text never panics; a set
//! that reads is written as GeoJSON (which reads back), WKT and SVG to a
//! sink.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::io::Write;
use umbra::{
    polygon_set_to_svg, read_geojson_str, write_geojson_string, write_wkt_string, ReadOptions,
    RingOrientation,
};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for options in [ReadOptions::default(), ReadOptions::keep_orientation()] {
        let Ok(set) = read_geojson_str(text, options) else {
            continue;
        };
        let mut sink = std::io::sink();
        if let Ok(out) = write_geojson_string(&set, RingOrientation::AsWritten) {
            sink.write_all(out.as_bytes()).unwrap();
            read_geojson_str(&out, ReadOptions::keep_orientation())
                .expect("written GeoJSON reads back");
        }
        if let Ok(out) = write_wkt_string(&set, RingOrientation::ByRole) {
            sink.write_all(out.as_bytes()).unwrap();
        }
        if let Ok((svg, _)) = polygon_set_to_svg(&set) {
            sink.write_all(svg.as_bytes()).unwrap();
        }
    }
});
