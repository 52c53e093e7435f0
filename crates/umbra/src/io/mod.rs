//! File input and output (feature `io`): 2D polygon sets as WKT and
//! GeoJSON, 3D meshes as OBJ and OFF, `geo-types` conversions, and the
//! dispatch by file extension ([`FileKind`]). Every reader names the file
//! and the problem in its error; a reader never panics.

mod files;
mod geo;
mod geojson;
mod mesh_text;
mod rings;
mod wkt;

pub use files::{read_mesh, read_polygon_set, write_mesh, write_polygon_set, FileKind};
pub use geo::{from_geo, to_geo};
pub use geojson::{
    parse_geojson_polygons, polygons_to_geojson, read_geojson_file, read_geojson_str,
    write_geojson_file, write_geojson_string,
};
pub use mesh_text::{mesh_to_obj, mesh_to_off, parse_obj, parse_off, MeshReadOptions};
pub use rings::{layout_polygons, PolygonLayout, Polygons, RingOrientation};
pub use wkt::{
    parse_wkt_polygons, polygons_to_wkt, read_wkt_file, read_wkt_str, write_wkt_file,
    write_wkt_string, ReadOptions,
};
