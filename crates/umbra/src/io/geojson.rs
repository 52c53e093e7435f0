//! GeoJSON (RFC 7946) reading and writing of 2D polygon sets.
//!
//! Read: a `Polygon`, `MultiPolygon`, `GeometryCollection` of those, a
//! `Feature` with such a geometry (or a `null` one, skipped) or a
//! `FeatureCollection` of features. Points and lines (`Point`,
//! `MultiPoint`, `LineString`, `MultiLineString`, as GEOS and shapely
//! overlays return beside polygons, or features of another layer) are
//! skipped and counted ([`crate::PolygonSetRead::skipped_non_areal`]), as
//! the WKT reader skips them; a document with no polygonal part at all is
//! refused. Positions may carry a third number
//! (altitude, RFC 7946 section 3.1.1), which is ignored. Rings are taken by
//! role or as written, exactly as for WKT ([`crate::ReadOptions`]).
//!
//! Write: one `Polygon` or a `MultiPolygon` geometry, rings closed, outer
//! rings counter-clockwise and holes clockwise (RFC 7946 section 3.1.6, the
//! dissertation's interior-on-the-left convention). Coordinates are printed
//! in the shortest form that reads back to the same `f64`.

use super::rings::{build_set, strip_closing, validate_polygons, NonAreal};
use crate::{layout_polygons, Polygons, ReadOptions, RingOrientation, UmbraError};
use robust_arith::Point2;
use serde_json::Value;
use std::path::Path;
use topology::PolygonSet2;

const FORMAT: &str = "GeoJSON";

fn malformed(file: &str, message: impl Into<String>) -> UmbraError {
    UmbraError::Malformed {
        file: file.to_string(),
        format: FORMAT,
        message: message.into(),
    }
}

/// Reads GeoJSON text into polygons of open rings; `file` names the source
/// in errors. Points and lines are skipped (see the module docs).
pub fn parse_geojson_polygons(text: &str, file: &str) -> Result<Polygons, UmbraError> {
    parse_geojson_polygons_counted(text, file).map(|(polygons, _)| polygons)
}

/// [`parse_geojson_polygons`] and the number of non-areal parts skipped.
fn parse_geojson_polygons_counted(text: &str, file: &str) -> Result<(Polygons, usize), UmbraError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim().is_empty() {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    // serde_json limits nesting (128 levels), so hostile input cannot
    // exhaust the stack.
    let value: Value = serde_json::from_str(text).map_err(|e| malformed(file, e.to_string()))?;
    let mut polygons = Polygons::new();
    let mut skipped = NonAreal::default();
    collect(&value, file, &mut polygons, &mut skipped, "the document")?;
    skipped.finish(polygons, file)
}

/// Reads GeoJSON text into a polygon set. Errors name the source as
/// `<string>`.
///
/// ```
/// use umbra::{read_geojson_str, ReadOptions};
/// let set = read_geojson_str(
///     r#"{"type": "Polygon", "coordinates": [[[0, 0], [0, 2], [2, 2], [2, 0], [0, 0]]]}"#,
///     ReadOptions::default(),
/// ).unwrap();
/// // Stored clockwise, read by role as an outer ring: positive area.
/// assert_eq!(set.signed_area(), 4.0);
/// ```
pub fn read_geojson_str(text: &str, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    parse_set(text, "<string>", options).map(|(set, _)| set)
}

/// Reads a GeoJSON file into a polygon set; errors name the file. Points
/// and lines are skipped (see the module docs).
pub fn read_geojson_file(path: &Path, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    read_geojson_file_counted(path, options).map(|(set, _)| set)
}

/// [`read_geojson_file`] and the number of non-areal parts skipped.
pub(crate) fn read_geojson_file_counted(
    path: &Path,
    options: ReadOptions,
) -> Result<(PolygonSet2, usize), UmbraError> {
    let file = path.display().to_string();
    let text = super::files::read_text(path, FORMAT)?;
    parse_set(&text, &file, options)
}

/// Parses, validates and builds; the set and the non-areal parts skipped.
fn parse_set(
    text: &str,
    file: &str,
    options: ReadOptions,
) -> Result<(PolygonSet2, usize), UmbraError> {
    let (polygons, skipped) = parse_geojson_polygons_counted(text, file)?;
    if options.validate_coordinates {
        validate_polygons(&polygons, file)?;
    }
    Ok((build_set(&polygons, options.orientation, file)?, skipped))
}

/// Appends the polygons of one GeoJSON object and skips its points and
/// lines.
fn collect(
    v: &Value,
    file: &str,
    out: &mut Polygons,
    skipped: &mut NonAreal,
    what: &str,
) -> Result<(), UmbraError> {
    let obj = v
        .as_object()
        .ok_or_else(|| malformed(file, format!("{what} is not a JSON object")))?;
    let kind = obj
        .get("type")
        .and_then(Value::as_str)
        .ok_or_else(|| malformed(file, format!("{what} has no \"type\" string")))?;
    let member = |name: &str| {
        obj.get(name)
            .ok_or_else(|| malformed(file, format!("{what} ({kind}) has no \"{name}\"")))
    };
    let array = |name: &str| -> Result<&Vec<Value>, UmbraError> {
        member(name)?.as_array().ok_or_else(|| {
            malformed(
                file,
                format!("\"{name}\" of {what} ({kind}) is not an array"),
            )
        })
    };
    match kind {
        "FeatureCollection" => {
            for (i, f) in array("features")?.iter().enumerate() {
                collect(f, file, out, skipped, &format!("feature {}", i + 1))?;
            }
        }
        "Feature" => {
            let g = member("geometry")?;
            if !g.is_null() {
                collect(g, file, out, skipped, &format!("the geometry of {what}"))?;
            }
        }
        "GeometryCollection" => {
            for (i, g) in array("geometries")?.iter().enumerate() {
                collect(
                    g,
                    file,
                    out,
                    skipped,
                    &format!("geometry {} of {what}", i + 1),
                )?;
            }
        }
        "Polygon" => {
            let rings = array("coordinates")?;
            out.push(polygon(rings, file, out.len())?);
        }
        "MultiPolygon" => {
            for p in array("coordinates")? {
                let rings = p.as_array().ok_or_else(|| {
                    malformed(
                        file,
                        format!("polygon {} is not an array of rings", out.len() + 1),
                    )
                })?;
                out.push(polygon(rings, file, out.len())?);
            }
        }
        "Point" | "MultiPoint" | "LineString" | "MultiLineString" => {
            skipped.skip(|| format!("GeoJSON {kind} in {what}"));
        }
        other => {
            return Err(malformed(
                file,
                format!("{what} has unknown type \"{}\"", shorten(other)),
            ));
        }
    }
    Ok(())
}

fn shorten(s: &str) -> String {
    if s.chars().count() > 40 {
        format!("{}...", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}

/// One polygon: an array of rings, each an array of positions.
fn polygon(rings: &[Value], file: &str, index: usize) -> Result<Vec<Vec<Point2>>, UmbraError> {
    let mut out = Vec::with_capacity(rings.len());
    for (ri, ring) in rings.iter().enumerate() {
        let where_ = |qi: Option<usize>| match qi {
            Some(q) => format!("polygon {}, ring {}, point {}", index + 1, ri + 1, q + 1),
            None => format!("polygon {}, ring {}", index + 1, ri + 1),
        };
        let positions = ring.as_array().ok_or_else(|| {
            malformed(
                file,
                format!("{} is not an array of positions", where_(None)),
            )
        })?;
        let mut pts = Vec::with_capacity(positions.len());
        for (qi, pos) in positions.iter().enumerate() {
            let nums = pos.as_array().filter(|a| a.len() >= 2).ok_or_else(|| {
                malformed(
                    file,
                    format!(
                        "{}: a position must be an array of 2 or 3 numbers",
                        where_(Some(qi))
                    ),
                )
            })?;
            if nums.len() > 3 {
                return Err(malformed(
                    file,
                    format!(
                        "{}: a position has {} numbers (at most 3)",
                        where_(Some(qi)),
                        nums.len()
                    ),
                ));
            }
            let mut p = [0.0; 2];
            for (axis, slot) in p.iter_mut().enumerate() {
                *slot = nums[axis].as_f64().ok_or_else(|| {
                    malformed(
                        file,
                        format!(
                            "{}: coordinate {} is not a number",
                            where_(Some(qi)),
                            axis + 1
                        ),
                    )
                })?;
            }
            if nums.len() == 3 && !nums[2].is_number() {
                return Err(malformed(
                    file,
                    format!("{}: the altitude is not a number", where_(Some(qi))),
                ));
            }
            pts.push(p);
        }
        strip_closing(&mut pts);
        out.push(pts);
    }
    Ok(out)
}

/// GeoJSON text of polygons of open rings (each ring closed on output): a
/// `Polygon` for one polygon, a `MultiPolygon` otherwise.
pub fn polygons_to_geojson(polygons: &Polygons) -> String {
    let ring_json = |ring: &Vec<Point2>| -> Value {
        let mut pts: Vec<Value> = ring.iter().map(|p| Value::from(vec![p[0], p[1]])).collect();
        if let Some(first) = ring.first() {
            pts.push(Value::from(vec![first[0], first[1]]));
        }
        Value::Array(pts)
    };
    let poly_json =
        |rings: &Vec<Vec<Point2>>| -> Value { Value::Array(rings.iter().map(ring_json).collect()) };
    let value = if polygons.len() == 1 {
        serde_json::json!({ "type": "Polygon", "coordinates": poly_json(&polygons[0]) })
    } else {
        serde_json::json!({
            "type": "MultiPolygon",
            "coordinates": Value::Array(polygons.iter().map(poly_json).collect()),
        })
    };
    value.to_string() + "\n"
}

/// Writes a polygon set as GeoJSON text (see [`crate::layout_polygons`] for
/// the ring layout).
///
/// ```
/// use umbra::{write_geojson_string, read_geojson_str, PolygonSet2, ReadOptions, RingOrientation};
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [0.5, 0.25]]);
/// let text = write_geojson_string(&s, RingOrientation::ByRole).unwrap();
/// assert_eq!(text, "{\"coordinates\":[[[0.0,0.0],[1.0,0.0],[0.5,0.25],[0.0,0.0]]],\"type\":\"Polygon\"}\n");
/// assert_eq!(read_geojson_str(&text, ReadOptions::default()).unwrap().signed_area(), 0.125);
/// ```
pub fn write_geojson_string(
    set: &PolygonSet2,
    orientation: RingOrientation,
) -> Result<String, UmbraError> {
    let layout = layout_polygons(set, orientation, "<output>")?;
    Ok(polygons_to_geojson(&layout.polygons))
}

/// Writes a polygon set to a GeoJSON file. Returns the number of orphan
/// holes (see [`crate::PolygonLayout::orphan_holes`]).
pub fn write_geojson_file(
    path: &Path,
    set: &PolygonSet2,
    orientation: RingOrientation,
) -> Result<usize, UmbraError> {
    let file = path.display().to_string();
    let layout = layout_polygons(set, orientation, &file)?;
    std::fs::write(path, polygons_to_geojson(&layout.polygons)).map_err(|source| {
        UmbraError::Io {
            file,
            action: "write",
            source,
        }
    })?;
    Ok(layout.orphan_holes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn feature_collection_with_holes_and_altitudes() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
                [[0, 0, 5], [4, 0, 5], [4, 4, 5], [0, 4, 5], [0, 0, 5]],
                [[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]]]}},
            {"type": "Feature", "geometry": null},
            {"type": "Feature", "geometry": {"type": "MultiPolygon", "coordinates": [
                [[[10, 0], [11, 0], [11, 1], [10, 1], [10, 0]]]]}}]}"#;
        let set = read_geojson_str(text, ReadOptions::default()).unwrap();
        // 16 - 4 (the hole, stored counter-clockwise, read by role) + 1.
        assert_eq!(set.signed_area(), 13.0);
        let out = write_geojson_string(&set, RingOrientation::ByRole).unwrap();
        let back = read_geojson_str(&out, ReadOptions::keep_orientation()).unwrap();
        assert_eq!(back.signed_area(), 13.0);
    }

    /// Points and lines in a collection or as features beside polygons,
    /// empty or not, are skipped and counted (as the WKT reader does); a
    /// document of nothing else is refused, naming the first.
    #[test]
    fn points_and_lines_are_skipped_beside_polygons() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [
                {"type": "Polygon", "coordinates": [
                    [[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]],
                    [[1, 1], [1, 3], [3, 3], [3, 1], [1, 1]]]},
                {"type": "LineString", "coordinates": [[4, 0], [9, 0]]},
                {"type": "Point", "coordinates": []},
                {"type": "GeometryCollection", "geometries": [
                    {"type": "MultiPoint", "coordinates": [[1, 1], [2, 2]]}]}]}},
            {"type": "Feature", "geometry": {"type": "LineString", "coordinates": []}},
            {"type": "Feature", "geometry": {"type": "MultiLineString", "coordinates": [[[0, 0], [1, 1]]]}},
            {"type": "Feature", "geometry": {"type": "MultiPolygon", "coordinates": [
                [[[10, 0], [11, 0], [11, 2], [10, 2], [10, 0]]]]}}]}"#;
        let (set, skipped) = parse_set(text, "x.geojson", ReadOptions::default()).unwrap();
        assert_eq!(set.signed_area(), 16.0 - 4.0 + 2.0);
        assert_eq!(set.vertex_count(), 12);
        assert_eq!(skipped, 5);
        let only_lines = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": {"type": "LineString", "coordinates": []}},
            {"type": "Feature", "geometry": {"type": "Point", "coordinates": [1, 2]}}]}"#;
        assert_eq!(
            parse_set(only_lines, "x.geojson", ReadOptions::default())
                .unwrap_err()
                .to_string(),
            "x.geojson: unsupported geometry: GeoJSON LineString in the geometry of feature 1 (expected POLYGON or MULTIPOLYGON)"
        );
        // A collection of nothing is the empty set, without a skip.
        let (set, skipped) = parse_set(
            r#"{"type": "GeometryCollection", "geometries": []}"#,
            "x.geojson",
            ReadOptions::default(),
        )
        .unwrap();
        assert_eq!((set.is_empty(), skipped), (true, 0));
    }

    #[test]
    fn errors_name_the_problem() {
        let cases = [
            ("", "empty"),
            ("{", "malformed GeoJSON"),
            ("[1, 2]", "not a JSON object"),
            (r#"{"type": "Polygon"}"#, "has no \"coordinates\""),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1]]]}"#,
                "2 or 3 numbers",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, "x"]]]}"#,
                "not a number",
            ),
            (
                r#"{"type": "LineString", "coordinates": [[0, 0], [1, 1]]}"#,
                "LineString",
            ),
            (r#"{"type": "Banana"}"#, "unknown type"),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1e400, 0], [1, 1]]]}"#,
                "malformed",
            ),
        ];
        for (text, want) in cases {
            let err = read_geojson_str(text, ReadOptions::default())
                .unwrap_err()
                .to_string();
            assert!(err.contains(want), "{text:?}: {err}");
            assert!(!err.contains('\n'));
        }
    }
}
