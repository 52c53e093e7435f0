//! File input and output (feature `io`): 2D polygon sets as WKT and
//! GeoJSON (read and write) and SVG (write); 3D meshes as OBJ, OFF, STL, PLY,
//! 3MF and glTF, binary and JSON (read and write); `geo-types`
//! conversions; and the dispatch by file extension ([`FileKind`]). Every
//! reader names the file, the line or record, and the problem in its
//! error; a reader never panics, and no count in a file makes it reserve
//! more memory than the file's size can justify.

mod files;
mod geo;
mod geojson;
mod gltf;
mod gltf_read;
mod mesh_text;
mod origin;
mod ply;
mod rings;
mod stl;
mod svg;
mod text;
mod threemf;
mod threemf_read;
mod weld;
mod wkt;
mod wkt_diagnose;

pub use files::{
    read_mesh, read_polygon_set, read_polygon_set_counted, write_mesh, write_mesh_with,
    write_polygon_set, FileKind, MeshWriteOptions,
};
pub(crate) use files::{rename_output, wrong_dimension_of};
pub use geo::{from_geo, to_geo};
pub use geojson::{
    parse_geojson_polygons, polygons_to_geojson, read_geojson_file, read_geojson_str,
    write_geojson_file, write_geojson_string,
};
pub use gltf::{mesh_to_glb, mesh_to_gltf};
pub use gltf_read::parse_glb;
pub(crate) use mesh_text::{faces_split, obj_of_faces, off_of_faces};
pub use mesh_text::{mesh_to_obj, mesh_to_off, parse_obj, parse_off, MeshReadOptions};
pub(crate) use ply::ply_of_faces;
pub use ply::{mesh_to_ply, parse_ply};
pub use rings::{layout_polygons, PolygonLayout, PolygonSetRead, Polygons, RingOrientation};
pub use stl::{mesh_to_stl, parse_stl};
pub(crate) use stl::{triangles_stl, triangles_to_stl};
pub use svg::polygon_set_to_svg;
pub use threemf::mesh_to_3mf;
pub(crate) use threemf::{triangles_3mf, triangles_to_3mf};
pub use threemf_read::parse_3mf;
pub(crate) use weld::welded;
pub use wkt::{
    parse_wkt_polygons, polygons_to_wkt, read_wkt_file, read_wkt_str, write_wkt_file,
    write_wkt_string, ReadOptions,
};
