//! The options of a picture, their limits, and the error type.

use std::fmt;
use std::str::FromStr;
use topology::TopologyError;

/// The largest width or height of a picture, in pixels.
pub const MAX_SIDE: u32 = 16_384;

/// The largest number of pixels of a picture (8192 x 8192): about 200 MB
/// for a raster with its depth and facet buffers.
pub const MAX_PIXELS: u64 = 1 << 26;

/// The colour that marks problems ([`RenderOptions::highlight`]); no shade
/// of the pictures ever equals it.
pub const HIGHLIGHT: [u8; 3] = [230, 20, 120];

/// The direction a 3D mesh is seen from (orthographic, z up).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum View {
    /// From the front, right and above (direction `(1, -1, 1)`).
    #[default]
    Iso,
    /// From the front (along +y; x to the right, z up).
    Front,
    /// From above (along -z; x to the right, y up).
    Top,
    /// From the right side (along -x; y to the right, z up).
    Side,
}

impl View {
    /// Every view.
    pub const ALL: [View; 4] = [View::Iso, View::Front, View::Top, View::Side];

    /// The view's name (`"iso"`).
    pub fn name(self) -> &'static str {
        match self {
            View::Iso => "iso",
            View::Front => "front",
            View::Top => "top",
            View::Side => "side",
        }
    }
}

impl FromStr for View {
    type Err = String;
    fn from_str(s: &str) -> Result<View, String> {
        View::ALL
            .into_iter()
            .find(|v| v.name() == s)
            .ok_or_else(|| format!("unknown view '{s}' (iso, front, top or side)"))
    }
}

/// How a shape is drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Style {
    /// 2D: regions shaded by winding number, boundaries drawn thin; 3D:
    /// shaded facets.
    #[default]
    Filled,
    /// 2D: directed edges with one arrowhead per unit of multiplicity and
    /// vertices as dots, over a pale winding shade; 3D: shaded facets with
    /// their visible outlines.
    Topology,
}

impl Style {
    /// The style's name (`"filled"`).
    pub fn name(self) -> &'static str {
        match self {
            Style::Filled => "filled",
            Style::Topology => "topology",
        }
    }
}

impl FromStr for Style {
    type Err = String;
    fn from_str(s: &str) -> Result<Style, String> {
        [Style::Filled, Style::Topology]
            .into_iter()
            .find(|v| v.name() == s)
            .ok_or_else(|| format!("unknown style '{s}' (filled or topology)"))
    }
}

/// The options of a picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct RenderOptions {
    /// The view of a 3D mesh (2D sets are always seen from above).
    pub view: View,
    /// The width in pixels (SVG: user units).
    pub width: u32,
    /// The height in pixels (SVG: user units).
    pub height: u32,
    /// The style.
    pub style: Style,
    /// 3D: mark what the mesh check finds in [`HIGHLIGHT`].
    pub highlight: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            view: View::Iso,
            width: 800,
            height: 600,
            style: Style::Filled,
            highlight: false,
        }
    }
}

impl RenderOptions {
    /// Checks the size: each side in `1..=MAX_SIDE` and at most
    /// [`MAX_PIXELS`] pixels.
    pub fn validate(&self) -> Result<(), RenderError> {
        let (w, h) = (self.width, self.height);
        let reason = if w == 0 || h == 0 {
            Some("each side must be at least 1 pixel")
        } else if w > MAX_SIDE || h > MAX_SIDE {
            Some("each side must be at most 16384 pixels")
        } else if u64::from(w) * u64::from(h) > MAX_PIXELS {
            Some("at most 67108864 pixels (8192 x 8192)")
        } else {
            None
        };
        match reason {
            Some(reason) => Err(RenderError::BadSize {
                width: w,
                height: h,
                reason,
            }),
            None => Ok(()),
        }
    }
}

/// Why a picture could not be made.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum RenderError {
    /// The picture size is out of range.
    BadSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
        /// The limit broken.
        reason: &'static str,
    },
    /// The shape has a bad coordinate.
    InvalidShape(TopologyError),
    /// The options do not apply to the shape.
    Unsupported(&'static str),
    /// A bug: the PNG encoder failed on a well-formed image.
    Internal(String),
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenderError::BadSize {
                width,
                height,
                reason,
            } => write!(f, "picture size {width}x{height} refused: {reason}"),
            RenderError::InvalidShape(e) => write!(f, "cannot draw the shape: {e}"),
            RenderError::Unsupported(what) => f.write_str(what),
            RenderError::Internal(e) => {
                write!(f, "internal error (this is a bug, please report it): {e}")
            }
        }
    }
}

impl std::error::Error for RenderError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            RenderError::InvalidShape(e) => Some(e),
            _ => None,
        }
    }
}

impl From<TopologyError> for RenderError {
    fn from(e: TopologyError) -> Self {
        RenderError::InvalidShape(e)
    }
}
