//! The CSG tree: typed nodes, their JSON form (parsed with clear, located
//! errors; written back the same way) and builders.
//!
//! The JSON form of a node is an object with exactly one shape key:
//!
//! - `"op": "union" | "intersection" | "difference"` with `"children": [node, ...]`
//!   (at least one; difference is the first child minus all the others);
//! - `"box": {"size": [x, y, z], "center": false}` (corner at the origin
//!   unless centred; `"size": s` for a cube);
//! - `"sphere": {"radius": r, "segments": 32}` (a UV sphere, centred,
//!   `segments / 2` latitude bands, at least 2);
//! - `"cylinder": {"radius": r, "radius_top": r2, "height": h, "segments": 32,
//!   "center": false}` (axis z, from z = 0 unless centred; `radius_top`
//!   optional, 0 gives a cone);
//! - `"torus": {"radius": R, "tube": r, "segments": [32, 16]}` (axis z,
//!   centred);
//! - `"file": "relative/path.obj"` (a mesh file, relative to the script;
//!   a closed mesh whose facets face inward is turned outward);
//!
//! and optionally `"translate": [x, y, z]`, `"rotate": [ax, ay, az]`
//! (degrees, about x, then y, then z) and `"scale": s` or `[sx, sy, sz]`,
//! applied to the node's result in the order scale, rotate, translate.

use super::error::ModelError;
use super::primitives::{check_positive, check_segments, MAX_PRIMITIVE_FACETS};
use super::transform::{Scale, Transform};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};
use std::path::{Path, PathBuf};
use topology::BooleanOp;

/// The default segment count of spheres and cylinders.
pub const DEFAULT_SEGMENTS: u32 = 32;
/// The default segment counts of a torus (around the axis, around the tube).
pub const DEFAULT_TORUS_SEGMENTS: [u32; 2] = [32, 16];

/// A box leaf.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxSpec {
    /// The edge lengths.
    pub size: [f64; 3],
    /// Centred on the origin (else a corner at the origin).
    pub center: bool,
}

/// A UV sphere leaf (centred).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereSpec {
    /// The radius.
    pub radius: f64,
    /// The meridian count; the latitude bands are `max(2, segments / 2)`.
    pub segments: u32,
}

impl SphereSpec {
    /// The latitude band count.
    pub fn rings(&self) -> u32 {
        (self.segments / 2).max(2)
    }
}

/// A cylinder or cone leaf (axis z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CylinderSpec {
    /// The bottom radius.
    pub radius: f64,
    /// The top radius (`None`: the same as the bottom; 0: a cone).
    pub radius_top: Option<f64>,
    /// The height.
    pub height: f64,
    /// The segment count around the axis.
    pub segments: u32,
    /// Centred on the origin (else from z = 0).
    pub center: bool,
}

/// A torus leaf (axis z, centred).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TorusSpec {
    /// The distance from the axis to the tube's centre circle.
    pub radius: f64,
    /// The tube radius.
    pub tube: f64,
    /// Segments around the axis and around the tube.
    pub segments: [u32; 2],
}

/// What a CSG node is.
#[derive(Clone, Debug, PartialEq)]
pub enum CsgShape {
    /// A Boolean of the children.
    Op {
        /// The operation.
        op: BooleanOp,
        /// The children (at least one).
        children: Vec<CsgNode>,
    },
    /// A box.
    Box(BoxSpec),
    /// A UV sphere.
    Sphere(SphereSpec),
    /// A cylinder or cone.
    Cylinder(CylinderSpec),
    /// A torus.
    Torus(TorusSpec),
    /// A mesh file.
    File(PathBuf),
}

impl CsgShape {
    /// The JSON key of the shape (`op` for an operation).
    pub fn kind(&self) -> &'static str {
        match self {
            CsgShape::Op { op, .. } => op.name(),
            CsgShape::Box(_) => "box",
            CsgShape::Sphere(_) => "sphere",
            CsgShape::Cylinder(_) => "cylinder",
            CsgShape::Torus(_) => "torus",
            CsgShape::File(_) => "file",
        }
    }
}

/// A node of a CSG tree: a shape and the transform applied to its result.
#[derive(Clone, Debug, PartialEq)]
pub struct CsgNode {
    /// The shape.
    pub shape: CsgShape,
    /// Scale, rotate, translate (applied to the shape's result).
    pub transform: Transform,
}

/// The path of a node for messages: `children[2].children[0]`, or `root`.
pub(crate) fn path_string(path: &[usize]) -> String {
    if path.is_empty() {
        return "root".to_string();
    }
    path.iter()
        .map(|i| format!("children[{i}]"))
        .collect::<Vec<_>>()
        .join(".")
}

impl BoxSpec {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), ModelError> {
        for (i, &s) in self.size.iter().enumerate() {
            check_positive(&format!("box.size[{i}]"), s)?;
        }
        Ok(())
    }
}

impl SphereSpec {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), ModelError> {
        check_positive("sphere.radius", self.radius)?;
        check_segments("sphere.segments", self.segments, 3)?;
        let facets = u64::from(self.segments) * u64::from(self.rings());
        if facets > MAX_PRIMITIVE_FACETS {
            return Err(ModelError::param(
                "sphere.segments",
                format!("gives {facets} facets, more than {MAX_PRIMITIVE_FACETS}"),
            ));
        }
        Ok(())
    }
}

impl CylinderSpec {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), ModelError> {
        check_positive("cylinder.radius", self.radius)?;
        if let Some(r) = self.radius_top {
            if !r.is_finite() || r < 0.0 {
                return Err(ModelError::param(
                    "cylinder.radius_top",
                    format!("must be finite and >= 0, not {r}"),
                ));
            }
        }
        check_positive("cylinder.height", self.height)?;
        check_segments("cylinder.segments", self.segments, 3)
    }
}

impl TorusSpec {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), ModelError> {
        check_positive("torus.radius", self.radius)?;
        check_positive("torus.tube", self.tube)?;
        if self.tube >= self.radius {
            return Err(ModelError::param(
                "torus.tube",
                format!(
                    "must be < torus.radius ({}), not {}",
                    self.radius, self.tube
                ),
            ));
        }
        check_segments("torus.segments[0]", self.segments[0], 3)?;
        check_segments("torus.segments[1]", self.segments[1], 3)?;
        let facets = u64::from(self.segments[0]) * u64::from(self.segments[1]);
        if facets > MAX_PRIMITIVE_FACETS {
            return Err(ModelError::param(
                "torus.segments",
                format!("give {facets} facets, more than {MAX_PRIMITIVE_FACETS}"),
            ));
        }
        Ok(())
    }
}

// ---------------------------------------------------------------- parsing

const NODE_KEYS: [&str; 10] = [
    "op",
    "children",
    "box",
    "sphere",
    "cylinder",
    "torus",
    "file",
    "translate",
    "rotate",
    "scale",
];
const SHAPE_KEYS: [&str; 6] = ["op", "box", "sphere", "cylinder", "torus", "file"];

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The fields of a spec object, checked against the allowed keys.
struct Fields<'a> {
    what: &'static str,
    map: &'a Map<String, Value>,
}

impl<'a> Fields<'a> {
    fn new(what: &'static str, v: &'a Value, allowed: &[&str]) -> Result<Self, String> {
        let Value::Object(map) = v else {
            return Err(format!("{what} must be an object, not {}", type_name(v)));
        };
        for k in map.keys() {
            if !allowed.contains(&k.as_str()) {
                return Err(format!(
                    "{what}: unknown key \"{k}\" (expected {})",
                    allowed.join(", ")
                ));
            }
        }
        Ok(Fields { what, map })
    }

    fn get(&self, key: &str) -> Option<&'a Value> {
        self.map.get(key)
    }

    fn required(&self, key: &str) -> Result<&'a Value, String> {
        self.get(key)
            .ok_or_else(|| format!("{}.{key} is missing", self.what))
    }

    fn number(&self, key: &str) -> Result<f64, String> {
        number(&format!("{}.{key}", self.what), self.required(key)?)
    }

    fn opt_number(&self, key: &str) -> Result<Option<f64>, String> {
        self.get(key)
            .map(|v| number(&format!("{}.{key}", self.what), v))
            .transpose()
    }

    fn bool_or(&self, key: &str, default: bool) -> Result<bool, String> {
        match self.get(key) {
            None => Ok(default),
            Some(Value::Bool(b)) => Ok(*b),
            Some(v) => Err(format!(
                "{}.{key} must be true or false, not {}",
                self.what,
                type_name(v)
            )),
        }
    }

    fn count_or(&self, key: &str, default: u32) -> Result<u32, String> {
        self.get(key)
            .map_or(Ok(default), |v| count(&format!("{}.{key}", self.what), v))
    }
}

fn number(name: &str, v: &Value) -> Result<f64, String> {
    v.as_f64()
        .ok_or_else(|| format!("{name} must be a number, not {}", type_name(v)))
}

fn count(name: &str, v: &Value) -> Result<u32, String> {
    if let Some(n) = v.as_u64() {
        return u32::try_from(n).map_err(|_| format!("{name} is too large ({n})"));
    }
    match v {
        Value::Number(_) => Err(format!("{name} must be a non-negative integer, not {v}")),
        _ => Err(format!("{name} must be an integer, not {}", type_name(v))),
    }
}

fn triple(name: &str, v: &Value) -> Result<[f64; 3], String> {
    match v {
        Value::Array(a) if a.len() == 3 => {
            let mut out = [0.0; 3];
            for (i, x) in a.iter().enumerate() {
                out[i] = number(&format!("{name}[{i}]"), x)?;
            }
            Ok(out)
        }
        _ => Err(format!("{name} must be an array of 3 numbers")),
    }
}

fn param_message(e: ModelError) -> String {
    match e {
        ModelError::InvalidParameter { param, message } => format!("{param} {message}"),
        other => other.to_string(),
    }
}

fn parse_shape(key: &str, obj: &Map<String, Value>) -> Result<CsgShape, String> {
    let v = &obj[key];
    let shape = match key {
        "op" => {
            let op = match v {
                Value::String(s) => match s.as_str() {
                    "union" => BooleanOp::Union,
                    "intersection" => BooleanOp::Intersection,
                    "difference" => BooleanOp::Difference,
                    other => {
                        return Err(format!(
                        "op must be \"union\", \"intersection\" or \"difference\", not \"{other}\""
                    ))
                    }
                },
                _ => return Err(format!("op must be a string, not {}", type_name(v))),
            };
            match obj.get("children") {
                None => return Err(format!("{} needs \"children\"", op.name())),
                Some(Value::Array(c)) if c.is_empty() => {
                    return Err(format!("{} needs at least one child", op.name()))
                }
                Some(Value::Array(_)) => {}
                Some(c) => return Err(format!("children must be an array, not {}", type_name(c))),
            }
            // Children are parsed by the caller (they carry their own paths).
            CsgShape::Op {
                op,
                children: Vec::new(),
            }
        }
        "box" => {
            let f = Fields::new("box", v, &["size", "center"])?;
            let size = match f.required("size")? {
                s @ Value::Number(_) => {
                    let x = number("box.size", s)?;
                    [x; 3]
                }
                s => triple("box.size", s)?,
            };
            let spec = BoxSpec {
                size,
                center: f.bool_or("center", false)?,
            };
            spec.validate().map_err(param_message)?;
            CsgShape::Box(spec)
        }
        "sphere" => {
            let f = Fields::new("sphere", v, &["radius", "segments"])?;
            let spec = SphereSpec {
                radius: f.number("radius")?,
                segments: f.count_or("segments", DEFAULT_SEGMENTS)?,
            };
            spec.validate().map_err(param_message)?;
            CsgShape::Sphere(spec)
        }
        "cylinder" => {
            let f = Fields::new(
                "cylinder",
                v,
                &["radius", "radius_top", "height", "segments", "center"],
            )?;
            let spec = CylinderSpec {
                radius: f.number("radius")?,
                radius_top: f.opt_number("radius_top")?,
                height: f.number("height")?,
                segments: f.count_or("segments", DEFAULT_SEGMENTS)?,
                center: f.bool_or("center", false)?,
            };
            spec.validate().map_err(param_message)?;
            CsgShape::Cylinder(spec)
        }
        "torus" => {
            let f = Fields::new("torus", v, &["radius", "tube", "segments"])?;
            let segments = match f.get("segments") {
                None => DEFAULT_TORUS_SEGMENTS,
                Some(Value::Array(a)) if a.len() == 2 => [
                    count("torus.segments[0]", &a[0])?,
                    count("torus.segments[1]", &a[1])?,
                ],
                Some(_) => return Err("torus.segments must be an array of 2 integers".into()),
            };
            let spec = TorusSpec {
                radius: f.number("radius")?,
                tube: f.number("tube")?,
                segments,
            };
            spec.validate().map_err(param_message)?;
            CsgShape::Torus(spec)
        }
        "file" => match v {
            Value::String(s) if !s.is_empty() => CsgShape::File(PathBuf::from(s)),
            Value::String(_) => return Err("file must not be empty".into()),
            _ => return Err(format!("file must be a string, not {}", type_name(v))),
        },
        _ => return Err(format!("unknown shape \"{key}\"")),
    };
    Ok(shape)
}

fn parse_transform(obj: &Map<String, Value>) -> Result<Transform, String> {
    let mut t = Transform::default();
    if let Some(v) = obj.get("translate") {
        t.translate = Some(triple("translate", v)?);
    }
    if let Some(v) = obj.get("rotate") {
        t.rotate = Some(triple("rotate", v)?);
    }
    if let Some(v) = obj.get("scale") {
        t.scale = Some(match v {
            Value::Number(_) => Scale::Uniform(number("scale", v)?),
            Value::Array(_) => Scale::Axes(
                triple("scale", v)
                    .map_err(|_| "scale must be a number or an array of 3 numbers")?,
            ),
            _ => {
                return Err(format!(
                    "scale must be a number or an array of 3 numbers, not {}",
                    type_name(v)
                ))
            }
        });
    }
    t.validate().map_err(param_message)?;
    Ok(t)
}

/// The deepest nesting a script may have.
pub const MAX_DEPTH: usize = 256;

fn parse_node(v: &Value, path: &mut Vec<usize>, file: &str) -> Result<CsgNode, ModelError> {
    let err = |path: &[usize], message: String| ModelError::Script {
        file: file.to_string(),
        node: path_string(path),
        message,
    };
    if path.len() > MAX_DEPTH {
        return Err(err(path, format!("nesting deeper than {MAX_DEPTH}")));
    }
    let Value::Object(obj) = v else {
        return Err(err(
            path,
            format!("a node must be an object, not {}", type_name(v)),
        ));
    };
    if let Some(k) = obj.keys().find(|k| !NODE_KEYS.contains(&k.as_str())) {
        return Err(err(
            path,
            format!("unknown key \"{k}\" (expected {})", NODE_KEYS.join(", ")),
        ));
    }
    let kinds: Vec<&str> = SHAPE_KEYS
        .iter()
        .copied()
        .filter(|k| obj.contains_key(*k))
        .collect();
    let key = match kinds.as_slice() {
        [] => {
            return Err(err(
                path,
                format!("no shape (expected one of {})", SHAPE_KEYS.join(", ")),
            ))
        }
        [k] => *k,
        several => {
            return Err(err(
                path,
                format!(
                    "several shapes ({}); a node has exactly one",
                    several.join(", ")
                ),
            ))
        }
    };
    if key != "op" && obj.contains_key("children") {
        return Err(err(
            path,
            format!("\"children\" given to a {key} (only an op has children)"),
        ));
    }
    let mut shape = parse_shape(key, obj).map_err(|m| err(path, m))?;
    let transform = parse_transform(obj).map_err(|m| err(path, m))?;
    if let CsgShape::Op { children, .. } = &mut shape {
        if let Some(Value::Array(list)) = obj.get("children") {
            for (i, c) in list.iter().enumerate() {
                path.push(i);
                let child = parse_node(c, path, file);
                path.pop();
                children.push(child?);
            }
        }
    }
    Ok(CsgNode { shape, transform })
}

/// Parses a CSG tree from its JSON value; `file` names the script in
/// messages.
pub fn parse_csg_value(value: &Value, file: &str) -> Result<CsgNode, ModelError> {
    parse_node(value, &mut Vec::new(), file)
}

/// Parses a CSG tree from JSON text. `file` leaves keep their paths as
/// written (see [`CsgNode::resolve_files`]).
pub fn parse_csg(text: &str) -> Result<CsgNode, ModelError> {
    parse_csg_named(text, "<string>")
}

fn parse_csg_named(text: &str, file: &str) -> Result<CsgNode, ModelError> {
    // serde_json refuses nesting beyond 128 JSON levels (its parser is
    // recursive: the limit keeps a hostile script from overflowing the
    // stack). An operation takes two of them (its object and its children's
    // list), so the message says what that means for a tree.
    let value: Value = serde_json::from_str(text).map_err(|e| ModelError::Json {
        file: file.to_string(),
        message: if e.to_string().starts_with("recursion limit exceeded") {
            format!(
                "{e}: a script may nest about 60 operations deep (128 JSON levels); \
                 give a chain of Booleans as one operation with many children"
            )
        } else {
            e.to_string()
        },
    })?;
    parse_csg_value(&value, file)
}

/// Reads and parses a CSG script; relative `file` leaves are resolved
/// against the script's directory.
pub fn read_csg_file(path: &Path) -> Result<CsgNode, ModelError> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| ModelError::Io {
        file: name.clone(),
        source,
    })?;
    let text = String::from_utf8(bytes).map_err(|e| ModelError::Json {
        file: name.clone(),
        message: format!(
            "not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ),
    })?;
    let mut node = parse_csg_named(&text, &name)?;
    let base = path.parent().unwrap_or(Path::new(""));
    node.resolve_files(base);
    Ok(node)
}

// ---------------------------------------------------------------- writing

fn f64_value(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

fn triple_value(a: [f64; 3]) -> Value {
    Value::Array(a.iter().map(|&x| f64_value(x)).collect())
}

impl CsgNode {
    /// The node's JSON form (parsing it gives the same tree).
    pub fn to_json_value(&self) -> Value {
        let mut m = Map::new();
        match &self.shape {
            CsgShape::Op { op, children } => {
                m.insert("op".into(), Value::String(op.name().into()));
                m.insert(
                    "children".into(),
                    Value::Array(children.iter().map(CsgNode::to_json_value).collect()),
                );
            }
            CsgShape::Box(b) => {
                let mut s = Map::new();
                s.insert("size".into(), triple_value(b.size));
                s.insert("center".into(), Value::Bool(b.center));
                m.insert("box".into(), Value::Object(s));
            }
            CsgShape::Sphere(b) => {
                let mut s = Map::new();
                s.insert("radius".into(), f64_value(b.radius));
                s.insert("segments".into(), Value::from(b.segments));
                m.insert("sphere".into(), Value::Object(s));
            }
            CsgShape::Cylinder(c) => {
                let mut s = Map::new();
                s.insert("radius".into(), f64_value(c.radius));
                if let Some(r) = c.radius_top {
                    s.insert("radius_top".into(), f64_value(r));
                }
                s.insert("height".into(), f64_value(c.height));
                s.insert("segments".into(), Value::from(c.segments));
                s.insert("center".into(), Value::Bool(c.center));
                m.insert("cylinder".into(), Value::Object(s));
            }
            CsgShape::Torus(t) => {
                let mut s = Map::new();
                s.insert("radius".into(), f64_value(t.radius));
                s.insert("tube".into(), f64_value(t.tube));
                s.insert(
                    "segments".into(),
                    Value::Array(vec![t.segments[0].into(), t.segments[1].into()]),
                );
                m.insert("torus".into(), Value::Object(s));
            }
            CsgShape::File(p) => {
                m.insert("file".into(), Value::String(p.display().to_string()));
            }
        }
        if let Some(t) = self.transform.translate {
            m.insert("translate".into(), triple_value(t));
        }
        if let Some(r) = self.transform.rotate {
            m.insert("rotate".into(), triple_value(r));
        }
        match self.transform.scale {
            Some(Scale::Uniform(s)) => {
                m.insert("scale".into(), f64_value(s));
            }
            Some(Scale::Axes(a)) => {
                m.insert("scale".into(), triple_value(a));
            }
            None => {}
        }
        Value::Object(m)
    }

    /// The node's JSON text, pretty-printed.
    pub fn to_json_string(&self) -> String {
        // A Value always serialises.
        serde_json::to_string_pretty(&self.to_json_value()).unwrap_or_default()
    }

    /// Joins every relative `file` path onto `base`.
    pub fn resolve_files(&mut self, base: &Path) {
        match &mut self.shape {
            CsgShape::File(p) if p.is_relative() => *p = base.join(&*p),
            CsgShape::Op { children, .. } => {
                for c in children {
                    c.resolve_files(base);
                }
            }
            _ => {}
        }
    }

    /// The mesh files the tree reads (its `file` leaves), in tree order.
    pub fn files(&self) -> Vec<&Path> {
        match &self.shape {
            CsgShape::File(p) => vec![p.as_path()],
            CsgShape::Op { children, .. } => children.iter().flat_map(CsgNode::files).collect(),
            _ => Vec::new(),
        }
    }

    /// The number of Booleans the evaluation runs: `k - 1` for an
    /// operation with `k` children.
    pub fn boolean_count(&self) -> usize {
        match &self.shape {
            CsgShape::Op { children, .. } => {
                children.len().saturating_sub(1)
                    + children.iter().map(CsgNode::boolean_count).sum::<usize>()
            }
            _ => 0,
        }
    }

    /// The depth of the tree (1 for a leaf), computed without recursion.
    pub fn depth(&self) -> usize {
        let mut deepest = 0;
        let mut stack = vec![(self, 1usize)];
        while let Some((node, d)) = stack.pop() {
            deepest = deepest.max(d);
            if let CsgShape::Op { children, .. } = &node.shape {
                stack.extend(children.iter().map(|c| (c, d + 1)));
            }
        }
        deepest
    }

    /// The number of leaves.
    pub fn leaf_count(&self) -> usize {
        match &self.shape {
            CsgShape::Op { children, .. } => children.iter().map(CsgNode::leaf_count).sum(),
            _ => 1,
        }
    }

    // ------------------------------------------------------------ builders

    fn leaf(shape: CsgShape) -> CsgNode {
        CsgNode {
            shape,
            transform: Transform::default(),
        }
    }

    /// A box leaf (corner at the origin unless `center`).
    pub fn cuboid(size: [f64; 3], center: bool) -> CsgNode {
        CsgNode::leaf(CsgShape::Box(BoxSpec { size, center }))
    }

    /// A UV sphere leaf.
    pub fn sphere(radius: f64, segments: u32) -> CsgNode {
        CsgNode::leaf(CsgShape::Sphere(SphereSpec { radius, segments }))
    }

    /// A cylinder leaf on the z axis from z = 0 (or centred).
    pub fn cylinder(radius: f64, height: f64, segments: u32, center: bool) -> CsgNode {
        CsgNode::leaf(CsgShape::Cylinder(CylinderSpec {
            radius,
            radius_top: None,
            height,
            segments,
            center,
        }))
    }

    /// A cone or frustum leaf on the z axis from z = 0 (or centred).
    pub fn cone(radius: f64, radius_top: f64, height: f64, segments: u32, center: bool) -> CsgNode {
        CsgNode::leaf(CsgShape::Cylinder(CylinderSpec {
            radius,
            radius_top: Some(radius_top),
            height,
            segments,
            center,
        }))
    }

    /// A torus leaf.
    pub fn torus(radius: f64, tube: f64, segments: [u32; 2]) -> CsgNode {
        CsgNode::leaf(CsgShape::Torus(TorusSpec {
            radius,
            tube,
            segments,
        }))
    }

    /// A mesh-file leaf.
    pub fn file(path: impl Into<PathBuf>) -> CsgNode {
        CsgNode::leaf(CsgShape::File(path.into()))
    }

    /// An operation node.
    pub fn op(op: BooleanOp, children: Vec<CsgNode>) -> CsgNode {
        CsgNode::leaf(CsgShape::Op { op, children })
    }

    /// The union of the children.
    pub fn union(children: Vec<CsgNode>) -> CsgNode {
        CsgNode::op(BooleanOp::Union, children)
    }

    /// The intersection of the children.
    pub fn intersection(children: Vec<CsgNode>) -> CsgNode {
        CsgNode::op(BooleanOp::Intersection, children)
    }

    /// The first child minus the others.
    pub fn difference(children: Vec<CsgNode>) -> CsgNode {
        CsgNode::op(BooleanOp::Difference, children)
    }

    /// This node wrapped in a one-child union (no Boolean), to carry a
    /// further transform.
    fn wrapped(self) -> CsgNode {
        CsgNode::union(vec![self])
    }

    /// The node translated by `t` after its own transform.
    pub fn translated(mut self, t: [f64; 3]) -> CsgNode {
        let old = self.transform.translate.unwrap_or([0.0; 3]);
        self.transform.translate = Some([old[0] + t[0], old[1] + t[1], old[2] + t[2]]);
        self
    }

    /// The node rotated by `r` (degrees about x, then y, then z) after its
    /// own transform.
    pub fn rotated(self, r: [f64; 3]) -> CsgNode {
        let mut n = if self.transform.translate.is_some() || self.transform.rotate.is_some() {
            self.wrapped()
        } else {
            self
        };
        n.transform.rotate = Some(r);
        n
    }

    /// The node scaled by `s` after its own transform.
    pub fn scaled(self, s: Scale) -> CsgNode {
        let mut n = if self.transform.is_identity() {
            self
        } else {
            self.wrapped()
        };
        n.transform.scale = Some(s);
        n
    }
}

impl Serialize for CsgNode {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.to_json_value().serialize(s)
    }
}

impl<'de> Deserialize<'de> for CsgNode {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        parse_csg_value(&v, "<value>").map_err(serde::de::Error::custom)
    }
}
