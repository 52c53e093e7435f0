//! `umbra render IN -o OUT.png|OUT.svg [--view V] [--size WxH] [--style S]
//! [--highlight]`: a picture of a 2D polygon file or a 3D mesh file.

use crate::errors::usage;
use crate::files::{refuse_overlaps, write_all};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use umbra::{
    read_mesh, render_mesh, render_mesh_svg, render_polygons,
    render_polygons_svg, FileKind, MeshReadOptions, ReadOptions, RenderError, RenderOptions,
    Style, View,
};

/// Draw a picture of a file: a 2D set shaded by winding number (or its
/// directed edges with arrowheads), a 3D mesh shaded and z-buffered.
#[derive(clap::Args, Debug)]
pub struct RenderArgs {
    /// The file to draw (2D: .wkt .geojson; 3D: .obj .off .stl .ply).
    input: PathBuf,
    /// The picture (.png or .svg).
    #[arg(short, long)]
    output: PathBuf,
    /// 3D: the direction the mesh is seen from.
    #[arg(long, value_enum, default_value_t = ViewArg::Iso)]
    view: ViewArg,
    /// The size in pixels, WxH (each side 1 to 16384, at most 8192x8192 in
    /// all).
    #[arg(long, value_parser = parse_size, default_value = "800x600")]
    size: (u32, u32),
    /// filled: shaded regions (2D: by winding number) or facets;
    /// topology: 2D directed edges with an arrowhead per unit of
    /// multiplicity and vertices as dots, 3D facet outlines.
    #[arg(long, value_enum, default_value_t = StyleArg::Filled)]
    style: StyleArg,
    /// 3D: mark what `umbra check` finds (open and non-manifold edges and
    /// vertices, self-intersecting facets) in magenta.
    #[arg(long)]
    highlight: bool,
    /// 2D: read every ring as written instead of by role (outer rings
    /// anticlockwise, holes clockwise), to see a file's own directions.
    #[arg(long)]
    keep_orientation: bool,
}

/// `--view`.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum ViewArg {
    Iso,
    Front,
    Top,
    Side,
}

/// `--style`.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum StyleArg {
    Filled,
    Topology,
}

/// Parses `WxH` and checks it against the picture limits.
fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("'{s}' is not WxH (e.g. 800x600)"))?;
    let side = |t: &str| {
        t.trim()
            .parse::<u32>()
            .map_err(|_| format!("'{s}' is not WxH with whole numbers (e.g. 800x600)"))
    };
    let (width, height) = (side(w)?, side(h)?);
    RenderOptions {
        width,
        height,
        ..RenderOptions::default()
    }
    .validate()
    .map_err(|e| e.to_string())?;
    Ok((width, height))
}

/// The picture formats, by the output's extension.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Picture {
    Png,
    Svg,
}

fn picture_kind(path: &Path) -> anyhow::Result<Picture> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("png") => Ok(Picture::Png),
        Some("svg") => Ok(Picture::Svg),
        _ => Err(usage(format!(
            "{}: a picture is written as .png or .svg",
            path.display()
        ))),
    }
}

impl RenderArgs {
    /// Reads the file, draws it and writes the picture.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let picture = picture_kind(&self.output)?;
        refuse_overlaps(
            &[("the output", self.output.as_path())],
            &[("the input", self.input.as_path())],
        )?;
        let opts = RenderOptions {
            view: match self.view {
                ViewArg::Iso => View::Iso,
                ViewArg::Front => View::Front,
                ViewArg::Top => View::Top,
                ViewArg::Side => View::Side,
            },
            width: self.size.0,
            height: self.size.1,
            style: match self.style {
                StyleArg::Filled => Style::Filled,
                StyleArg::Topology => Style::Topology,
            },
            highlight: self.highlight,
        };
        let file = self.input.display().to_string();
        let failed = |e: RenderError| match e {
            RenderError::BadSize { .. } | RenderError::Unsupported(_) => {
                usage(format!("{file}: {e}"))
            }
            e => anyhow::anyhow!("{file}: {e}"),
        };
        let bytes = if FileKind::from_path(&self.input)?.is_mesh() {
            let mesh = read_mesh(&self.input, MeshReadOptions::default(), false)?;
            match picture {
                Picture::Png => render_mesh(&mesh, &opts).and_then(|i| i.to_png()),
                Picture::Svg => render_mesh_svg(&mesh, &opts).map(String::into_bytes),
            }
        } else {
            let options = ReadOptions {
                orientation: super::orientation(self.keep_orientation),
                ..ReadOptions::default()
            };
            let set = super::read_set(&self.input, options)?;
            match picture {
                Picture::Png => render_polygons(&set, &opts).and_then(|i| i.to_png()),
                Picture::Svg => render_polygons_svg(&set, &opts).map(String::into_bytes),
            }
        }
        .map_err(failed)?;
        write_all(&[(self.output.as_path(), bytes.as_slice())])?;
        Ok(ExitCode::SUCCESS)
    }
}
