//! Garbage input never panics: every prefix of a valid file, random edits
//! of valid text and random token soup either read as a topologically valid
//! set with valid coordinates (which the Boolean and the checks then accept)
//! or give an error naming the source on one line.

use proptest::prelude::*;
use umbra::{
    boolean, check_polygon_set, read_wkt_str, write_wkt_string, BooleanOp, PolygonSet2,
    ReadOptions, RingOrientation,
};

const VALID: &str = "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 4, 4 4, 4 2, 2 2)), ((12 0, 14 1, 12 2, 12 0)))";

/// Reads `text` both ways; on success runs the downstream operations and
/// asserts their contracts, on failure checks the message shape.
fn exercise(text: &str) {
    for options in [
        ReadOptions::default(),
        ReadOptions::keep_orientation(),
        ReadOptions {
            validate_coordinates: false,
            ..ReadOptions::default()
        },
    ] {
        match read_wkt_str(text, options) {
            Ok(set) => {
                assert!(set.check_topology().is_ok(), "{text}");
                let report = check_polygon_set(&set);
                assert!(report.topologically_valid);
                if !options.validate_coordinates {
                    continue;
                }
                assert!(set.validate_coordinates().is_ok(), "{text}");
                let mut square = PolygonSet2::new();
                square.add_loop(&[[1.0, 1.0], [11.0, 1.0], [11.0, 3.0], [1.0, 3.0]]);
                for op in BooleanOp::BASIC {
                    let out = boolean(&set, &square, op).unwrap();
                    assert!(out.shape.check_topology().is_ok(), "{text}");
                    write_wkt_string(&out.shape, RingOrientation::ByRole).unwrap();
                    write_wkt_string(&out.shape, RingOrientation::AsWritten).unwrap();
                }
            }
            Err(e) => {
                let msg = e.to_string();
                assert!(msg.starts_with("<string>: "), "{msg}");
                assert!(!msg.contains('\n'), "{msg}");
            }
        }
    }
}

#[test]
fn every_prefix_of_a_valid_file() {
    for (i, _) in VALID.char_indices() {
        exercise(&VALID[..i]);
    }
    exercise(VALID);
}

fn token() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        "(",
        ")",
        ",",
        " ",
        "0",
        "1",
        "-2.5",
        "1e308",
        "1e-320",
        "NaN",
        "inf",
        "-inf",
        "POLYGON",
        "MULTIPOLYGON",
        "GEOMETRYCOLLECTION",
        "EMPTY",
        "Z",
        "POINT",
        "LINESTRING",
        "\n",
        "x",
        "((",
        "))",
        "-",
        ".",
        "e",
        "+",
    ])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(256)))]

    #[test]
    fn random_edits_of_valid_text(edits in prop::collection::vec((0usize..200, token()), 1..6)) {
        let mut text = VALID.to_string();
        for (pos, tok) in edits {
            let at = pos % (text.len() + 1);
            if text.is_char_boundary(at) {
                text.insert_str(at, tok);
            }
        }
        exercise(&text);
    }

    #[test]
    fn random_token_soup(tokens in prop::collection::vec(token(), 0..40)) {
        exercise(&tokens.concat());
    }

    #[test]
    fn random_polygons_of_random_coordinates(
        rings in prop::collection::vec(prop::collection::vec((any::<f64>(), any::<f64>()), 0..6), 1..4)
    ) {
        let body: Vec<String> = rings
            .iter()
            .map(|r| {
                let pts: Vec<String> = r.iter().map(|(x, y)| format!("{x:e} {y:e}")).collect();
                format!("({})", pts.join(", "))
            })
            .collect();
        exercise(&format!("POLYGON ({})", body.join(", ")));
    }
}
