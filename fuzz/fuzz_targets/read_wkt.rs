//! Fuzz target: the WKT reader on any bytes (as a file would be decoded:
//! UTF-8 or an error) never panics; a set that reads is written as WKT,
//! GeoJSON and SVG to a sink, and the WKT written as it is reads back to
//! the same text.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::io::Write;
use umbra::{
    polygon_set_to_svg, read_wkt_str, write_geojson_string, write_wkt_string, ReadOptions,
    RingOrientation,
};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for options in [ReadOptions::default(), ReadOptions::keep_orientation()] {
        let Ok(set) = read_wkt_str(text, options) else {
            continue;
        };
        let mut sink = std::io::sink();
        if let Ok(out) = write_wkt_string(&set, RingOrientation::AsWritten) {
            sink.write_all(out.as_bytes()).unwrap();
            let back = read_wkt_str(&out, ReadOptions::keep_orientation())
                .expect("written WKT reads back");
            assert_eq!(
                write_wkt_string(&back, RingOrientation::AsWritten).unwrap(),
                out,
                "WKT round trip"
            );
        }
        if let Ok(out) = write_geojson_string(&set, RingOrientation::ByRole) {
            sink.write_all(out.as_bytes()).unwrap();
        }
        if let Ok((svg, _)) = polygon_set_to_svg(&set) {
            sink.write_all(svg.as_bytes()).unwrap();
        }
    }
});
