//! Cameras: orthographic front (looking down -z), side (looking down -x),
//! top (looking down -y) and perspective with yaw and pitch about the
//! mesh centre. Screen coordinates are pixels with y down; depth grows away
//! from the viewer.

use crate::mesh::Mesh;

/// Viewing direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum View {
    /// From +z towards -z, y up.
    Front,
    /// From +x towards -x, y up (the character's left side).
    Side,
    /// From +y towards -y, -z up.
    Top,
    /// Perspective from yaw (about y, degrees) and pitch (degrees), with a
    /// vertical field of view of 35 degrees.
    Perspective { yaw: f64, pitch: f64 },
}

impl std::str::FromStr for View {
    type Err = String;
    fn from_str(s: &str) -> Result<View, String> {
        match s {
            "front" => Ok(View::Front),
            "side" => Ok(View::Side),
            "top" => Ok(View::Top),
            "persp" | "perspective" => Ok(View::Perspective {
                yaw: 35.0,
                pitch: 20.0,
            }),
            _ => Err(format!(
                "unknown view {s:?} (expected front, side, top or perspective)"
            )),
        }
    }
}

/// A fitted camera.
#[derive(Clone, Debug)]
pub struct Camera {
    /// Rows: camera right, up, backward (towards the viewer) in world space.
    rot: [[f64; 3]; 3],
    centre: [f64; 3],
    scale: f64,
    width: f64,
    height: f64,
    /// Distance from the centre for perspective (None: orthographic).
    distance: Option<f64>,
    focal: f64,
}

impl Camera {
    /// A camera for `view` that frames `m`'s bounding box with `margin`.
    pub fn fit(m: &Mesh, view: View, width: usize, height: usize, margin: f64) -> Camera {
        let (lo, hi) = if m.positions.is_empty() {
            ([-1.0; 3], [1.0; 3])
        } else {
            m.bbox()
        };
        Camera::fit_box(lo, hi, view, width, height, margin)
    }

    /// A camera that frames the box `[lo, hi]`.
    pub fn fit_box(
        lo: [f64; 3],
        hi: [f64; 3],
        view: View,
        width: usize,
        height: usize,
        margin: f64,
    ) -> Camera {
        let centre = [
            (lo[0] + hi[0]) / 2.0,
            (lo[1] + hi[1]) / 2.0,
            (lo[2] + hi[2]) / 2.0,
        ];
        let rot = match view {
            View::Front => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            View::Side => [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
            View::Top => [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
            View::Perspective { yaw, pitch } => {
                let (y, p) = (yaw.to_radians(), pitch.to_radians());
                let back = [y.sin() * p.cos(), p.sin(), y.cos() * p.cos()];
                let right = crate::surface::normalize(crate::surface::cross([0.0, 1.0, 0.0], back));
                let up = crate::surface::cross(back, right);
                [right, up, back]
            }
        };
        let (w, h) = (width as f64, height as f64);
        let half_diag = 0.5
            * ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2) + (hi[2] - lo[2]).powi(2)).sqrt();
        let mut cam = Camera {
            rot,
            centre,
            scale: 1.0,
            width: w,
            height: h,
            distance: None,
            focal: 1.0,
        };
        let usable = (1.0 - 2.0 * margin).max(0.1);
        if let View::Perspective { .. } = view {
            let fov = 35f64.to_radians();
            let dist = half_diag.max(1e-9) / (fov / 2.0).sin();
            cam.distance = Some(dist);
            cam.focal = (h / 2.0) * usable / (fov / 2.0).tan();
        } else {
            // fit the projected box extents
            let mut ext: [f64; 2] = [1e-12, 1e-12];
            for corner in 0..8 {
                let p = [
                    if corner & 1 == 0 { lo[0] } else { hi[0] },
                    if corner & 2 == 0 { lo[1] } else { hi[1] },
                    if corner & 4 == 0 { lo[2] } else { hi[2] },
                ];
                let v = cam.to_view(p);
                ext[0] = ext[0].max(v[0].abs());
                ext[1] = ext[1].max(v[1].abs());
            }
            cam.scale = ((w / 2.0) / ext[0]).min((h / 2.0) / ext[1]) * usable;
        }
        cam
    }

    /// Pixels per unit of an orthographic camera.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// The same camera with another orthographic scale (pixels per unit).
    pub fn with_scale(mut self, scale: f64) -> Camera {
        self.scale = scale;
        self
    }

    fn to_view(&self, p: [f64; 3]) -> [f64; 3] {
        let d = crate::mesh::sub(p, self.centre);
        [
            crate::mesh::dot(self.rot[0], d),
            crate::mesh::dot(self.rot[1], d),
            crate::mesh::dot(self.rot[2], d),
        ]
    }

    /// A world direction in camera axes (right, up, towards viewer).
    pub fn to_view_dir(&self, n: [f64; 3]) -> [f64; 3] {
        [
            crate::mesh::dot(self.rot[0], n),
            crate::mesh::dot(self.rot[1], n),
            crate::mesh::dot(self.rot[2], n),
        ]
    }

    /// Pixel coordinates `(x, y)` and depth of a world point.
    pub fn project(&self, p: [f64; 3]) -> [f64; 3] {
        let v = self.to_view(p);
        match self.distance {
            None => [
                self.width / 2.0 + self.scale * v[0],
                self.height / 2.0 - self.scale * v[1],
                -v[2],
            ],
            Some(d) => {
                let z = d - v[2];
                let z = z.max(1e-9);
                [
                    self.width / 2.0 + self.focal * v[0] / z,
                    self.height / 2.0 - self.focal * v[1] / z,
                    z,
                ]
            }
        }
    }
}
