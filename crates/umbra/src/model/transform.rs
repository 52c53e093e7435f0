//! Affine transforms (`glam::DMat4`) applied to meshes, and the
//! scale-rotate-translate transform of a CSG node.

use super::error::ModelError;
use glam::{DMat3, DMat4, DVec3};
use serde::{Deserialize, Serialize};
use topology::{PolygonMesh, TriangleMesh};

/// Checks that `m` is a finite affine map with a non-zero, finite
/// determinant; returns the determinant of its linear part.
fn check_affine(m: &DMat4) -> Result<f64, ModelError> {
    if !m.is_finite() {
        return Err(ModelError::param("transform", "must be finite"));
    }
    let row3 = m.row(3);
    if row3 != glam::DVec4::new(0.0, 0.0, 0.0, 1.0) {
        return Err(ModelError::param(
            "transform",
            format!("must be affine (last row 0 0 0 1), not {row3}"),
        ));
    }
    let det = DMat3::from_mat4(*m).determinant();
    if det == 0.0 || !det.is_finite() {
        return Err(ModelError::param(
            "transform",
            format!(
                "must be invertible (determinant {det}: a zero scale, or scales so small or large that their product leaves the f64 range)"
            ),
        ));
    }
    Ok(det)
}

fn apply(m: &DMat4, vertices: &[[f64; 3]], what: &str) -> Result<Vec<[f64; 3]>, ModelError> {
    let out: Vec<[f64; 3]> = vertices
        .iter()
        .map(|&v| m.transform_point3(DVec3::from_array(v)).to_array())
        .collect();
    for (i, v) in out.iter().enumerate() {
        for &c in v {
            robust_arith::validate_coordinate(c).map_err(|e| {
                ModelError::param(
                    "transform",
                    format!("moves {what} vertex {i} to a bad coordinate: {e}"),
                )
            })?;
        }
    }
    Ok(out)
}

/// The mesh with every vertex mapped by the affine transform `m`; when the
/// determinant is negative (a mirror) every half-edge is reversed so the
/// mesh still faces outward. A non-finite, non-affine or singular matrix,
/// or a vertex mapped beyond `f64::MAX / 4`, gives an error.
pub fn transform_mesh(mesh: &PolygonMesh, m: &DMat4) -> Result<PolygonMesh, ModelError> {
    let det = check_affine(m)?;
    let vertices = apply(m, &mesh.vertices, "mesh")?;
    let mut facets = mesh.facets.clone();
    if det < 0.0 {
        for f in &mut facets {
            for h in &mut f.half_edges {
                std::mem::swap(&mut h.start, &mut h.end);
            }
        }
    }
    Ok(PolygonMesh::new(vertices, facets))
}

/// [`transform_mesh`] for a triangle mesh.
pub fn transform_triangles(mesh: &TriangleMesh, m: &DMat4) -> Result<TriangleMesh, ModelError> {
    let det = check_affine(m)?;
    let vertices = apply(m, &mesh.vertices, "mesh")?;
    let mut triangles = mesh.triangles.clone();
    if det < 0.0 {
        for t in &mut triangles {
            t.swap(1, 2);
        }
    }
    Ok(TriangleMesh::new(vertices, triangles))
}

/// The scale of a CSG node: one factor or one per axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Scale {
    /// The same factor on every axis.
    Uniform(f64),
    /// A factor per axis.
    Axes([f64; 3]),
}

impl Scale {
    /// The factors per axis.
    pub fn factors(self) -> DVec3 {
        match self {
            Scale::Uniform(s) => DVec3::splat(s),
            Scale::Axes(a) => DVec3::from_array(a),
        }
    }
}

/// The transform a CSG node may carry: scale, then rotate (degrees about
/// x, then y, then z), then translate. `None` fields are the identity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Transform {
    /// The translation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub translate: Option<[f64; 3]>,
    /// The rotation angles in degrees, about x, then y, then z.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotate: Option<[f64; 3]>,
    /// The scale.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<Scale>,
}

/// `(cos, sin)` of an angle in degrees, exact at multiples of 90 degrees.
fn cos_sin_degrees(deg: f64) -> (f64, f64) {
    if deg % 90.0 == 0.0 {
        let quarter = (deg / 90.0).rem_euclid(4.0);
        return match quarter as u8 {
            0 => (1.0, 0.0),
            1 => (0.0, 1.0),
            2 => (-1.0, 0.0),
            _ => (0.0, -1.0),
        };
    }
    let r = deg.to_radians();
    (r.cos(), r.sin())
}

impl Transform {
    /// `true` when no field is set.
    pub fn is_identity(&self) -> bool {
        self.translate.is_none() && self.rotate.is_none() && self.scale.is_none()
    }

    /// A translation only.
    pub fn translation(t: [f64; 3]) -> Self {
        Transform {
            translate: Some(t),
            ..Transform::default()
        }
    }

    /// Checks every value: finite, scale factors non-zero. Returns the
    /// offending field and problem.
    pub fn validate(&self) -> Result<(), ModelError> {
        let fields = [
            ("translate", self.translate),
            ("rotate", self.rotate),
            ("scale", self.scale.map(|s| s.factors().to_array())),
        ];
        for (name, v) in fields {
            if let Some(v) = v {
                if let Some(c) = v.iter().find(|c| !c.is_finite()) {
                    return Err(ModelError::param(name, format!("must be finite, not {c}")));
                }
            }
        }
        if let Some(s) = self.scale {
            if s.factors().to_array().contains(&0.0) {
                return Err(ModelError::param("scale", "must be non-zero"));
            }
        }
        Ok(())
    }

    /// The matrix `T * Rz * Ry * Rx * S`.
    pub fn matrix(&self) -> DMat4 {
        let s = self.scale.map_or(DVec3::ONE, Scale::factors);
        let [ax, ay, az] = self.rotate.unwrap_or([0.0; 3]);
        let (cx, sx) = cos_sin_degrees(ax);
        let (cy, sy) = cos_sin_degrees(ay);
        let (cz, sz) = cos_sin_degrees(az);
        let rx = DMat3::from_cols(
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, cx, sx),
            DVec3::new(0.0, -sx, cx),
        );
        let ry = DMat3::from_cols(
            DVec3::new(cy, 0.0, -sy),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(sy, 0.0, cy),
        );
        let rz = DMat3::from_cols(
            DVec3::new(cz, sz, 0.0),
            DVec3::new(-sz, cz, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
        );
        let linear = rz * ry * rx * DMat3::from_diagonal(s);
        let t = DVec3::from_array(self.translate.unwrap_or([0.0; 3]));
        DMat4::from_mat3_translation(linear, t)
    }
}
