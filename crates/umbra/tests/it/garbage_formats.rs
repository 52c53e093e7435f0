//! The OBJ, OFF and GeoJSON readers and the mesh check on garbage: every
//! prefix of a valid file, random token soup and random bytes must give a
//! mesh/set or an error, never a panic; whatever parses is then checked
//! (`check_mesh`, `check_polygon_set`) without panicking either.

use proptest::prelude::*;
use umbra::{
    check_mesh, check_polygon_set, parse_geojson_polygons, parse_obj, parse_off, read_geojson_str,
    ReadOptions,
};

const OBJ: &str = include_str!("../../../../examples/cube.obj");
const OFF: &str = include_str!("../../../../examples/cube_shifted.off");
const GEOJSON: &str = include_str!("../../../../examples/a.geojson");

fn exercise(text: &str) {
    if let Ok(m) = parse_obj(text, "x.obj") {
        let _ = check_mesh(&m);
    }
    if let Ok(m) = parse_off(text, "x.off") {
        let _ = check_mesh(&m);
    }
    let _ = parse_geojson_polygons(text, "x.geojson");
    for options in [ReadOptions::default(), ReadOptions::keep_orientation()] {
        if let Ok(set) = read_geojson_str(text, options) {
            let _ = check_polygon_set(&set);
        }
    }
}

#[test]
fn every_prefix_of_valid_files() {
    for text in [OBJ, OFF, GEOJSON] {
        for end in (0..=text.len()).filter(|&i| text.is_char_boundary(i)) {
            exercise(&text[..end]);
        }
    }
}

fn token() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        "v",
        "f",
        "vn",
        "vt",
        "OFF",
        "COFF",
        "#",
        "\n",
        " ",
        "/",
        "//",
        "-1",
        "0",
        "1",
        "2",
        "3",
        "4",
        "8",
        "-9",
        "4294967296",
        "1e308",
        "nan",
        "inf",
        "-0",
        "0.5",
        "{",
        "}",
        "[",
        "]",
        ",",
        ":",
        "\"type\"",
        "\"Polygon\"",
        "\"MultiPolygon\"",
        "\"Feature\"",
        "\"FeatureCollection\"",
        "\"coordinates\"",
        "\"geometry\"",
        "\"features\"",
        "null",
    ])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(400)))]

    #[test]
    fn token_soup(tokens in proptest::collection::vec(token(), 0..80)) {
        exercise(&tokens.concat());
    }

    #[test]
    fn random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        exercise(&String::from_utf8_lossy(&bytes));
    }

    /// Random meshes with indices anywhere (dangling, repeated) and any
    /// coordinates: the check reports, never panics.
    #[test]
    fn random_index_meshes(
        coords in proptest::collection::vec(prop_oneof![Just(f64::NAN), Just(1e300), -2.0f64..2.0], 0..24),
        faces in proptest::collection::vec(proptest::collection::vec(0u32..10, 3..6), 0..8),
    ) {
        let mut text = String::new();
        for c in coords.chunks(3).filter(|c| c.len() == 3) {
            text += &format!("v {} {} {}\n", c[0], c[1], c[2]);
        }
        for f in &faces {
            text += "f";
            for v in f {
                text += &format!(" {}", v + 1);
            }
            text += "\n";
        }
        exercise(&text);
    }
}
