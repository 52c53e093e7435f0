//! WKT input and output of [`PolygonSet2`] (`POLYGON`, `MULTIPOLYGON`).
//!
//! A `GEOMETRYCOLLECTION` is read for its polygonal members; its points
//! and lines (which GEOS and shapely overlays return beside polygons) are
//! skipped and counted ([`crate::PolygonSetRead::skipped_non_areal`]), and
//! a file with no polygonal part at all is refused.
//!
//! Parsing uses the `wkt` crate after a structural pre-scan (balanced
//! parentheses, one geometry per file, bounded nesting) so that truncated
//! files and trailing text are reported instead of silently dropped.
//! Geometries with `Z`, `M` or `ZM` coordinates are read in the plane: the
//! third and fourth ordinates are dropped, as the GeoJSON reader drops the
//! altitude, and the `SRID=n;` prefix of extended WKT (PostGIS's
//! `ST_AsEWKT`) is accepted and ignored. The writer writes `x y` only.
//! Coordinates are written in Rust's shortest round-trip formatting, so a
//! write followed by a read gives the same `f64` values bit for bit.

use super::rings::{
    build_set, layout_polygons, strip_closing, validate_polygons, NonAreal, Polygons,
};
use super::text::strip_bom;
use super::wkt_diagnose::{diagnose, find_overflow};
use crate::{RingOrientation, UmbraError};
use robust_arith::Point2;
use std::fmt::Write as _;
use std::path::Path;
use std::str::FromStr;
use topology::PolygonSet2;
use wkt::types::Polygon;
use wkt::Wkt;

/// The deepest parenthesis nesting accepted (a `GEOMETRYCOLLECTION` of
/// `MULTIPOLYGON`s needs 4); it bounds the parser's recursion.
const MAX_NESTING: usize = 32;

/// Options for reading polygon files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ReadOptions {
    /// How ring directions are decided (by role by default).
    pub orientation: RingOrientation,
    /// Reject NaN, infinite and out-of-range coordinates (`true` by
    /// default). `umbra check` turns it off to report them instead.
    pub validate_coordinates: bool,
}

impl Default for ReadOptions {
    fn default() -> Self {
        ReadOptions {
            orientation: RingOrientation::ByRole,
            validate_coordinates: true,
        }
    }
}

impl ReadOptions {
    /// Options that keep every ring's stored direction.
    pub fn keep_orientation() -> Self {
        ReadOptions {
            orientation: RingOrientation::AsWritten,
            ..Self::default()
        }
    }
}

/// Reads WKT text (`POLYGON`, `MULTIPOLYGON`, or a `GEOMETRYCOLLECTION` of
/// those) into a polygon set. Errors name the source as `<string>`.
///
/// ```
/// use umbra::{read_wkt_str, ReadOptions};
/// let set = read_wkt_str("POLYGON ((0 0, 0 2, 2 2, 2 0, 0 0))", ReadOptions::default()).unwrap();
/// // Stored clockwise, read by role as an outer ring: positive area.
/// assert_eq!(set.signed_area(), 4.0);
/// assert_eq!(set.vertex_count(), 4);
/// ```
pub fn read_wkt_str(text: &str, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    parse_wkt(text, "<string>", options).map(|(set, _)| set)
}

/// Reads a WKT file into a polygon set; errors name the file. The points
/// and lines of a collection are skipped (see the module docs).
pub fn read_wkt_file(path: &Path, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    read_wkt_file_counted(path, options).map(|(set, _)| set)
}

/// [`read_wkt_file`] and the number of non-areal parts skipped.
pub(crate) fn read_wkt_file_counted(
    path: &Path,
    options: ReadOptions,
) -> Result<(PolygonSet2, usize), UmbraError> {
    let file = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| UmbraError::Io {
        file: file.clone(),
        action: "read",
        source,
    })?;
    let text = super::text::decode(&bytes, &file, "WKT")?;
    parse_wkt(text, &file, options)
}

/// Reads WKT text into polygons of open rings (no closing duplicates),
/// without building a set; `file` names the source in errors. The points
/// and lines of a collection are skipped (see the module docs).
///
/// ```
/// use umbra::parse_wkt_polygons;
/// let p = parse_wkt_polygons(
///     "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)), LINESTRING (0 0, 5 5), POINT EMPTY)",
///     "x.wkt",
/// ).unwrap();
/// assert_eq!(p, vec![vec![vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]]]);
/// let e = parse_wkt_polygons("LINESTRING (0 0, 5 5)", "x.wkt").unwrap_err().to_string();
/// assert_eq!(e, "x.wkt: unsupported geometry: LINESTRING (expected POLYGON or MULTIPOLYGON)");
/// ```
pub fn parse_wkt_polygons(text: &str, file: &str) -> Result<Polygons, UmbraError> {
    parse_wkt_polygons_counted(text, file).map(|(polygons, _)| polygons)
}

/// [`parse_wkt_polygons`] and the number of non-areal parts skipped.
fn parse_wkt_polygons_counted(text: &str, file: &str) -> Result<(Polygons, usize), UmbraError> {
    let text = strip_bom(text);
    let blanked = blank_srid(text, file)?;
    let text = blanked.as_deref().unwrap_or(text);
    if text.trim().is_empty() {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    prescan(text, file)?;
    if let Some(message) = find_overflow(text) {
        return Err(UmbraError::Parse {
            file: file.to_string(),
            message,
        });
    }
    let geometry = Wkt::<f64>::from_str(text).map_err(|msg| UmbraError::Parse {
        file: file.to_string(),
        message: diagnose(text).unwrap_or_else(|| explain_parse_error(text, msg)),
    })?;
    let mut polygons = Polygons::new();
    let mut skipped = NonAreal::default();
    collect_polygons(&geometry, "", &mut polygons, &mut skipped);
    skipped.finish(polygons, file)
}

/// Parses, validates and builds; the set and the non-areal parts skipped.
fn parse_wkt(
    text: &str,
    file: &str,
    options: ReadOptions,
) -> Result<(PolygonSet2, usize), UmbraError> {
    let (polygons, skipped) = parse_wkt_polygons_counted(text, file)?;
    if options.validate_coordinates {
        validate_polygons(&polygons, file)?;
    }
    Ok((build_set(&polygons, options.orientation, file)?, skipped))
}

/// The text with an extended-WKT `SRID=n;` prefix replaced by as many
/// spaces (so that positions in messages stay those of the file), or
/// `None` when there is no such prefix. A prefix without digits is an
/// error; the spatial reference itself is not interpreted.
fn blank_srid(text: &str, file: &str) -> Result<Option<String>, UmbraError> {
    let start = text.len() - text.trim_start().len();
    let rest = &text[start..];
    let has_prefix = rest
        .get(..5)
        .is_some_and(|p| p.eq_ignore_ascii_case("SRID="));
    if !has_prefix {
        return Ok(None);
    }
    let after = &rest[5..];
    let body = after.strip_prefix('-').unwrap_or(after);
    let digits = body.len() - body.trim_start_matches(|c: char| c.is_ascii_digit()).len();
    let end = start + 5 + (after.len() - body.len()) + digits;
    if digits == 0 || !text[end..].starts_with(';') {
        return Err(UmbraError::Parse {
            file: file.to_string(),
            message: format!(
                "malformed extended-WKT prefix at {}: expected 'SRID=<integer>;' before the geometry",
                position(text, start)
            ),
        });
    }
    let mut out = String::with_capacity(text.len());
    out.push_str(&text[..start]);
    out.extend(std::iter::repeat_n(' ', end + 1 - start));
    out.push_str(&text[end + 1..]);
    Ok(Some(out))
}

/// Checks the bracket structure: balanced, not nested too deeply, and
/// nothing but white space after the geometry.
fn prescan(text: &str, file: &str) -> Result<(), UmbraError> {
    let err = |message: String| UmbraError::Parse {
        file: file.to_string(),
        message,
    };
    let mut depth = 0usize;
    let mut saw_paren = false;
    for (i, c) in text.char_indices() {
        if saw_paren && depth == 0 {
            if !c.is_whitespace() {
                return Err(err(format!(
                    "unexpected text after the geometry at {} (one geometry per file)",
                    position(text, i)
                )));
            }
            continue;
        }
        match c {
            '(' => {
                depth += 1;
                saw_paren = true;
                if depth > MAX_NESTING {
                    return Err(err(format!(
                        "parentheses nested deeper than {MAX_NESTING} at {}",
                        position(text, i)
                    )));
                }
            }
            ')' => {
                if depth == 0 {
                    return Err(err(format!("unbalanced ')' at {}", position(text, i))));
                }
                depth -= 1;
            }
            _ => {}
        }
    }
    if depth > 0 {
        return Err(err(format!(
            "unexpected end of text with {depth} unclosed parenthesis(es) (the file looks truncated)"
        )));
    }
    if !saw_paren {
        // `TYPE EMPTY` or `TYPE Z EMPTY`.
        let words: Vec<&str> = text.split_whitespace().collect();
        let ends_empty = words
            .last()
            .is_some_and(|w| w.eq_ignore_ascii_case("EMPTY"));
        if words.len() > 3 || !ends_empty {
            return Err(err(format!(
                "expected a geometry with coordinates in parentheses or EMPTY, found '{}'",
                shorten(text.trim())
            )));
        }
    }
    Ok(())
}

/// `line L, column C` of byte offset `i` (1-based).
pub(crate) fn position(text: &str, i: usize) -> String {
    let before = text.get(..i).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    format!("line {line}, column {column}")
}

/// At most 40 characters of `s`, for messages.
fn shorten(s: &str) -> String {
    let mut out: String = s.chars().take(40).collect();
    if s.chars().count() > 40 {
        out.push_str("...");
    }
    out.replace(['\n', '\r'], " ")
}

/// Turns the `wkt` crate's message into one that says what is wrong: a word
/// such as `NaN` or `inf` where a number belongs is a non-finite coordinate.
fn explain_parse_error(text: &str, msg: &str) -> String {
    let non_finite = text
        .split(|c: char| c.is_whitespace() || c == '(' || c == ')' || c == ',')
        .find(|w| {
            w.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                && w.parse::<f64>().is_ok_and(|v| !v.is_finite())
        });
    match non_finite {
        Some(word) => format!("coordinate '{word}' is not a finite number"),
        None => format!("{msg} (truncated or not WKT?)"),
    }
}

/// The WKT keyword of a geometry, for messages.
fn kind(geometry: &Wkt<f64>) -> &'static str {
    match geometry {
        Wkt::Point(_) => "POINT",
        Wkt::LineString(_) => "LINESTRING",
        Wkt::Polygon(_) => "POLYGON",
        Wkt::MultiPoint(_) => "MULTIPOINT",
        Wkt::MultiLineString(_) => "MULTILINESTRING",
        Wkt::MultiPolygon(_) => "MULTIPOLYGON",
        Wkt::GeometryCollection(_) => "GEOMETRYCOLLECTION",
    }
}

/// Appends the polygons of `geometry` and skips its points and lines;
/// `context` says where a collection member sits, for messages.
fn collect_polygons(
    geometry: &Wkt<f64>,
    context: &str,
    out: &mut Polygons,
    skipped: &mut NonAreal,
) {
    match geometry {
        Wkt::Polygon(p) => out.push(open_rings(p)),
        Wkt::MultiPolygon(mp) => out.extend(mp.polygons().iter().map(open_rings)),
        Wkt::GeometryCollection(gc) => {
            for (i, member) in gc.geometries().iter().enumerate() {
                let ctx = format!("{context}GEOMETRYCOLLECTION member {} is a ", i + 1);
                collect_polygons(member, &ctx, out, skipped);
            }
        }
        Wkt::Point(_) | Wkt::LineString(_) | Wkt::MultiPoint(_) | Wkt::MultiLineString(_) => {
            skipped.skip(|| format!("{context}{}", kind(geometry)));
        }
    }
}

/// The rings of a WKT polygon without their closing duplicates, in the
/// plane (`z` and `m` dropped).
fn open_rings(p: &Polygon<f64>) -> Vec<Vec<Point2>> {
    p.rings()
        .iter()
        .map(|ring| {
            let mut pts: Vec<Point2> = ring.coords().iter().map(|c| [c.x, c.y]).collect();
            strip_closing(&mut pts);
            pts
        })
        .collect()
}

/// Writes a polygon set as WKT text (`POLYGON` for one polygon,
/// `MULTIPOLYGON` otherwise, `MULTIPOLYGON EMPTY` for the empty set), with a
/// final newline. See [`crate::layout_polygons`] for the ring layout.
///
/// ```
/// use umbra::{write_wkt_string, PolygonSet2, RingOrientation};
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [0.5, 0.25]]);
/// let text = write_wkt_string(&s, RingOrientation::ByRole).unwrap();
/// assert_eq!(text, "POLYGON ((0 0, 1 0, 0.5 0.25, 0 0))\n");
/// ```
pub fn write_wkt_string(
    set: &PolygonSet2,
    orientation: RingOrientation,
) -> Result<String, UmbraError> {
    wkt_text(set, orientation, "<output>").map(|(text, _)| text)
}

/// Writes a polygon set to a WKT file. Returns the number of orphan holes
/// (see [`crate::PolygonLayout::orphan_holes`]).
pub fn write_wkt_file(
    path: &Path,
    set: &PolygonSet2,
    orientation: RingOrientation,
) -> Result<usize, UmbraError> {
    let file = path.display().to_string();
    let (text, orphans) = wkt_text(set, orientation, &file)?;
    std::fs::write(path, text).map_err(|source| UmbraError::Io {
        file,
        action: "write",
        source,
    })?;
    Ok(orphans)
}

/// The WKT text and the orphan-hole count.
fn wkt_text(
    set: &PolygonSet2,
    orientation: RingOrientation,
    file: &str,
) -> Result<(String, usize), UmbraError> {
    let layout = layout_polygons(set, orientation, file)?;
    Ok((polygons_to_wkt(&layout.polygons), layout.orphan_holes))
}

/// WKT text of polygons of open rings (each ring is closed on output).
pub fn polygons_to_wkt(polygons: &Polygons) -> String {
    let mut out =
        String::with_capacity(32 + 48 * polygons.iter().flatten().map(Vec::len).sum::<usize>());
    match polygons.as_slice() {
        [] => out.push_str("MULTIPOLYGON EMPTY"),
        [single] => {
            out.push_str("POLYGON ");
            write_polygon(&mut out, single);
        }
        many => {
            out.push_str("MULTIPOLYGON (");
            for (i, poly) in many.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write_polygon(&mut out, poly);
            }
            out.push(')');
        }
    }
    out.push('\n');
    out
}

/// `((x y, ...), (x y, ...))`.
fn write_polygon(out: &mut String, rings: &[Vec<Point2>]) {
    out.push('(');
    for (i, ring) in rings.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        out.push('(');
        for (j, p) in ring.iter().chain(ring.first()).enumerate() {
            if j > 0 {
                out.push_str(", ");
            }
            write_coordinate(out, p[0]);
            out.push(' ');
            write_coordinate(out, p[1]);
        }
        out.push(')');
    }
    out.push(')');
}

/// The shortest decimal that reads back as the same `f64`: plain notation
/// for moderate magnitudes, exponent notation for very large or small ones.
fn write_coordinate(out: &mut String, v: f64) {
    let a = v.abs();
    // Writing to a String cannot fail.
    let _ = if a == 0.0 || (1.0e-5..1.0e16).contains(&a) {
        write!(out, "{v}")
    } else {
        write!(out, "{v:e}")
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn read(text: &str) -> Result<PolygonSet2, UmbraError> {
        read_wkt_str(text, ReadOptions::default())
    }

    #[test]
    fn closing_duplicate_is_not_a_vertex() {
        let s = read("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))").unwrap();
        assert_eq!(s.vertex_count(), 4);
        assert_eq!(s.edge_count(), 4);
        // An unclosed ring is closed implicitly.
        let s = read("POLYGON ((0 0, 1 0, 1 1, 0 1))").unwrap();
        assert_eq!(s.vertex_count(), 4);
        assert_eq!(s.signed_area(), 1.0);
    }

    #[test]
    fn degenerate_rings_are_valid_loops() {
        for text in [
            "POLYGON ((1 1, 1 1))",
            "POLYGON ((1 1, 2 2, 1 1))",
            "POLYGON ((0 0, 1 1, 2 2, 0 0))",
        ] {
            let s = read(text).unwrap();
            assert!(s.check_topology().is_ok(), "{text}");
            assert_eq!(s.signed_area(), 0.0);
        }
    }

    #[test]
    fn holes_read_by_role_or_as_written() {
        // Outer stored clockwise, hole stored counter-clockwise.
        let text = "POLYGON ((0 0, 0 4, 4 4, 4 0, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1))";
        assert_eq!(read(text).unwrap().signed_area(), 15.0);
        let kept = read_wkt_str(text, ReadOptions::keep_orientation()).unwrap();
        assert_eq!(kept.signed_area(), -16.0 + 1.0);
    }

    #[test]
    fn collections_of_polygons_are_accepted() {
        let s = read(
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)), MULTIPOLYGON (((5 5, 6 5, 6 6, 5 5))))",
        )
        .unwrap();
        assert_eq!(s.vertex_count(), 6);
        for empty in [
            "POLYGON EMPTY",
            "MULTIPOLYGON EMPTY",
            " GEOMETRYCOLLECTION EMPTY\n",
        ] {
            assert!(read(empty).unwrap().is_empty(), "{empty}");
        }
    }

    /// A collection's points and lines (GEOS and shapely overlays return
    /// them beside polygons), empty or not, nested or not, are skipped and
    /// counted; its polygons are read.
    #[test]
    fn collections_keep_their_polygons_and_skip_points_and_lines() {
        let text = "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1)), LINESTRING (4 0, 9 0), POINT (7 7), POINT EMPTY, GEOMETRYCOLLECTION (MULTIPOLYGON (((10 0, 11 0, 11 2, 10 2, 10 0))), MULTILINESTRING ((0 0, 1 1)), MULTIPOINT ((1 1), (2 2))), LINESTRING EMPTY)";
        let (set, skipped) = parse_wkt(text, "x.wkt", ReadOptions::default()).unwrap();
        assert_eq!(set.signed_area(), 16.0 - 4.0 + 2.0);
        assert_eq!(set.vertex_count(), 12);
        assert_eq!(skipped, 6);
        let (set, skipped) = parse_wkt(
            "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)))",
            "x.wkt",
            ReadOptions::default(),
        )
        .unwrap();
        assert_eq!((set.signed_area(), skipped), (0.5, 0));
        // An empty polygon beside a line is an empty set, not an error.
        let (set, skipped) = parse_wkt(
            "GEOMETRYCOLLECTION (POLYGON EMPTY, LINESTRING (0 0, 1 1))",
            "x.wkt",
            ReadOptions::default(),
        )
        .unwrap();
        assert_eq!((set.is_empty(), skipped), (true, 1));
    }

    #[test]
    fn bad_text_is_named_and_explained() {
        let cases = [
            ("", "empty"),
            ("   \n", "empty"),
            ("POINT (1 2)", "POINT"),
            ("LINESTRING (0 0, 1 1)", "LINESTRING"),
            ("POINT EMPTY", "unsupported geometry: POINT"),
            ("LINESTRING Z EMPTY", "unsupported geometry: LINESTRING"),
            (
                "GEOMETRYCOLLECTION (POINT (1 1), GEOMETRYCOLLECTION (LINESTRING EMPTY))",
                "unsupported geometry: GEOMETRYCOLLECTION member 1 is a POINT",
            ),
            ("POLYGON ((0 0, 1 0, 1", "truncated"),
            (
                "POLYGON ((0 0, 1 0, 1 1, 0 0)) POLYGON ((0 0, 1 0, 1 1, 0 0))",
                "after the geometry",
            ),
            ("POLYGON ((0 0, 1 0, 1 1, 0 0)))", "unexpected text after"),
            (
                "POLYGON ) ((0 0, 1 0, 1 1, 0 0))",
                "unbalanced ')' at line 1, column 9",
            ),
            ("POLYGON ((0 0, NaN 0, 1 1, 0 0))", "'NaN' is not a finite"),
            ("POLYGON ((0 0, inf 0, 1 1, 0 0))", "'inf' is not a finite"),
            ("POLYGON ((0 0, -inf 0, 1 1, 0 0))", "not finite"),
            (
                "POLYGON ((0 0, 1e309 0, 1 1, 0 0))",
                "'1e309' overflows f64 (beyond ±1.8e308, so not finite) at line 1, column 16",
            ),
            (
                "POLYGON ((0 0, 1 0, 1 x, 0 0))",
                "'x' at line 1, column 23 is not a number",
            ),
            (
                "POLYGON ((0 0, 1 1e308, 1 1, 0 0))",
                "polygon 1, ring 1, point 2: y coordinate 1e308 exceeds",
            ),
            (
                "POLYGON Z ((0 0, 1 0, 1 1, 0 0))",
                "a coordinate of 2 numbers ending at line 1, column 15, but this geometry's coordinates have 3",
            ),
            (
                "POLYGON ((0 0 1, 1 0 1, 1 1 1, 0 0 1))",
                "a coordinate of 3 numbers ending at line 1, column 15, but this geometry's coordinates have 2 (x y z or x y z m need the Z, M or ZM keyword",
            ),
            (
                "SRID=;POLYGON ((0 0, 1 0, 1 1, 0 0))",
                "malformed extended-WKT prefix at line 1, column 1",
            ),
            ("  srid=4326 POLYGON ((0 0, 1 0, 1 1, 0 0))", "'SRID=<integer>;'"),
            // Positions after an SRID prefix are those of the text.
            (
                "SRID=4326;POLYGON ((0 0, 1 0, 1 x, 0 0))",
                "'x' at line 1, column 33 is not a number",
            ),
            ("POLYGON ((0 0, 1 0, 1 x, 0 0))", "malformed WKT"),
            ("hello", "expected a geometry"),
            ("POLYGON EMPTY trailing words here", "expected a geometry"),
        ];
        for (text, needle) in cases {
            let err = read(text).unwrap_err().to_string();
            assert!(err.starts_with("<string>: "), "{text}: {err}");
            assert!(err.contains(needle), "{text}: {err}");
            assert!(!err.contains('\n'), "{text}: {err}");
        }
        let deep = format!(
            "GEOMETRYCOLLECTION {}{}",
            "(".repeat(100_000),
            ")".repeat(100_000)
        );
        assert!(read(&deep)
            .unwrap_err()
            .to_string()
            .contains("nested deeper"));
    }

    #[test]
    fn z_and_m_ordinates_and_srid_prefixes_are_read_in_the_plane() {
        let plain = read(
            "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), ((10 0, 11 0, 11 1, 10 0)))",
        )
        .unwrap();
        let as_written = |s: &PolygonSet2| write_wkt_string(s, RingOrientation::ByRole).unwrap();
        for text in [
            "MULTIPOLYGON Z (((0 0 5, 4 0 5, 4 4 5, 0 4 5, 0 0 5), (1 1 -1, 1 2 -1, 2 2 -1, 2 1 -1, 1 1 -1)), ((10 0 0, 11 0 1, 11 1 2, 10 0 3)))",
            "MULTIPOLYGON M (((0 0 5, 4 0 5, 4 4 5, 0 4 5, 0 0 5), (1 1 0, 1 2 0, 2 2 0, 2 1 0, 1 1 0)), ((10 0 0, 11 0 1, 11 1 2, 10 0 3)))",
            "MULTIPOLYGON ZM (((0 0 5 1, 4 0 5 1, 4 4 5 1, 0 4 5 1, 0 0 5 1), (1 1 0 0, 1 2 0 0, 2 2 0 0, 2 1 0 0, 1 1 0 0)), ((10 0 0 0, 11 0 1 0, 11 1 2 0, 10 0 3 0)))",
            "SRID=4326;MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), ((10 0, 11 0, 11 1, 10 0)))",
            " srid=-1;GEOMETRYCOLLECTION Z (POLYGON Z ((0 0 1, 4 0 1, 4 4 1, 0 4 1, 0 0 1), (1 1 1, 1 2 1, 2 2 1, 2 1 1, 1 1 1)), MULTIPOLYGON Z (((10 0 0, 11 0 0, 11 1 0, 10 0 0))))",
        ] {
            let set = read(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(as_written(&set), as_written(&plain), "{text}");
        }
        for empty in ["POLYGON Z EMPTY", "SRID=3857;MULTIPOLYGON ZM EMPTY"] {
            assert!(read(empty).unwrap().is_empty(), "{empty}");
        }
        // A word where a number belongs is refused in any ordinate.
        for text in [
            "POLYGON Z ((0 0 NaN, 1 0 0, 1 1 0, 0 0 0))",
            "POLYGON ZM ((0 0 0 inf, 1 0 0 0, 1 1 0 0, 0 0 0 0))",
        ] {
            let err = read(text).unwrap_err().to_string();
            assert!(err.contains("is not a finite number"), "{text}: {err}");
        }
    }

    #[test]
    fn writer_layout_and_empty() {
        assert_eq!(
            write_wkt_string(&PolygonSet2::new(), RingOrientation::ByRole).unwrap(),
            "MULTIPOLYGON EMPTY\n"
        );
        let s = read("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), ((10 0, 11 0, 11 1, 10 0)))").unwrap();
        let text = write_wkt_string(&s, RingOrientation::ByRole).unwrap();
        assert!(text.starts_with("MULTIPOLYGON ((("), "{text}");
        let back = read(&text).unwrap();
        assert_eq!(back.signed_area(), s.signed_area());
        assert_eq!(
            write_wkt_string(&back, RingOrientation::ByRole).unwrap(),
            text
        );
    }

    #[test]
    fn coordinates_round_trip_bit_exact_at_the_extremes() {
        let values = [
            0.1,
            -0.0,
            1.0 / 3.0,
            1.0e-300,
            5.0e-324,
            -f64::MIN_POSITIVE,
            1.0e15 + 0.5,
            123456789012345680.0,
            f64::MAX / 4.0,
            -f64::MAX / 4.0,
        ];
        for &v in &values {
            let mut s = String::new();
            write_coordinate(&mut s, v);
            let back: f64 = s.parse().unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v:e} -> {s}");
        }
    }

    /// The directed edges of a set as bit patterns of their end points,
    /// sorted (a multiset independent of vertex numbering and loop order).
    fn edge_bits(s: &PolygonSet2) -> Vec<[u64; 4]> {
        let mut v: Vec<[u64; 4]> = s
            .edges()
            .iter()
            .flat_map(|e| {
                let (a, b) = s.edge_points(e);
                let (a, b) = if e.mult >= 0 { (a, b) } else { (b, a) };
                let bits = [
                    a[0].to_bits(),
                    a[1].to_bits(),
                    b[0].to_bits(),
                    b[1].to_bits(),
                ];
                std::iter::repeat_n(bits, e.mult.unsigned_abs() as usize)
            })
            .collect();
        v.sort_unstable();
        v
    }

    /// A star-shaped (hence simple) counter-clockwise polygon around `c`.
    fn star(c: Point2, radii: &[f64]) -> Vec<Point2> {
        let n = radii.len();
        radii
            .iter()
            .enumerate()
            .map(|(i, &r)| {
                let t = std::f64::consts::TAU * i as f64 / n as f64;
                [c[0] + r * t.cos(), c[1] + r * t.sin()]
            })
            .collect()
    }

    fn any_coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![
            -1.0e6..1.0e6f64,
            (-1000i32..1000).prop_map(f64::from),
            any::<f64>().prop_filter("valid", |v| robust_arith::validate_coordinate(*v).is_ok()),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(128)))]

        /// Any loops, written as they are and read back as they are, give
        /// the same directed edges bit for bit.
        #[test]
        fn as_written_round_trip_is_bit_exact(
            loops in prop::collection::vec(prop::collection::vec([any_coordinate(), any_coordinate()], 1..8), 0..5)
        ) {
            let mut s = PolygonSet2::new();
            for l in &loops {
                s.add_loop(l);
            }
            let text = write_wkt_string(&s, RingOrientation::AsWritten).unwrap();
            let back = read_wkt_str(&text, ReadOptions::keep_orientation()).unwrap();
            prop_assert_eq!(edge_bits(&back), edge_bits(&s));
            prop_assert_eq!(write_wkt_string(&back, RingOrientation::AsWritten).unwrap(), text);
        }

        /// Disjoint simple polygons with holes (a hole of radius below 2.5
        /// lies inside a star of radii at least 5 and 3 or more points), in
        /// the by-role layout, read
        /// back to the same directed edges bit for bit.
        #[test]
        fn by_role_round_trip_is_bit_exact(
            shapes in prop::collection::vec(
                (prop::collection::vec(5.0..10.0f64, 3..9), prop::option::of(prop::collection::vec(0.5..2.4f64, 3..7))),
                1..4)
        ) {
            let mut s = PolygonSet2::new();
            for (i, (outer, hole)) in shapes.iter().enumerate() {
                let c = [30.0 * i as f64 + 0.1, -7.3];
                s.add_loop(&star(c, outer));
                if let Some(h) = hole {
                    let mut h = star(c, h);
                    h.reverse();
                    s.add_loop(&h);
                }
            }
            let text = write_wkt_string(&s, RingOrientation::ByRole).unwrap();
            let back = read_wkt_str(&text, ReadOptions::default()).unwrap();
            prop_assert_eq!(edge_bits(&back), edge_bits(&s));
            let holes = shapes.iter().filter(|(_, h)| h.is_some()).count();
            let separators = text.matches("), (").count() - text.matches(")), ((").count();
            prop_assert_eq!(separators, holes);
        }
    }
}
