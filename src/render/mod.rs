//! CPU rasteriser for previews and figures (no GPU): a depth buffer,
//! Blinn-Phong shading with per-group colours, optional polyline overlays,
//! orthographic front / side / top and perspective cameras, PNG output.

mod camera;

pub use camera::{Camera, View};

use crate::mesh::io::write_atomic;
use crate::mesh::{Mesh, MeshError};

/// An RGBA8 image.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub rgba: Vec<u8>,
}

impl Image {
    /// A uniformly coloured image.
    pub fn new(width: usize, height: usize, colour: [u8; 4]) -> Image {
        let mut rgba = Vec::with_capacity(width * height * 4);
        for _ in 0..width * height {
            rgba.extend_from_slice(&colour);
        }
        Image {
            width,
            height,
            rgba,
        }
    }

    /// Sets pixel `(x, y)` (ignored outside the image).
    pub fn put(&mut self, x: i64, y: i64, c: [u8; 4]) {
        if x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height {
            let o = 4 * (y as usize * self.width + x as usize);
            self.rgba[o..o + 4].copy_from_slice(&c);
        }
    }

    /// Pixel `(x, y)`.
    pub fn get(&self, x: usize, y: usize) -> [u8; 4] {
        let o = 4 * (y * self.width + x);
        [
            self.rgba[o],
            self.rgba[o + 1],
            self.rgba[o + 2],
            self.rgba[o + 3],
        ]
    }

    /// Images side by side (top-aligned, background-filled).
    pub fn hstack(images: &[Image], background: [u8; 4]) -> Image {
        let w = images.iter().map(|i| i.width).sum();
        let h = images.iter().map(|i| i.height).max().unwrap_or(0);
        let mut out = Image::new(w, h, background);
        let mut x0 = 0;
        for im in images {
            for y in 0..im.height {
                for x in 0..im.width {
                    out.put((x0 + x) as i64, y as i64, im.get(x, y));
                }
            }
            x0 += im.width;
        }
        out
    }

    /// PNG bytes.
    pub fn encode_png(&self) -> Vec<u8> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width as u32, self.height as u32);
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            // writing into a Vec cannot fail
            if let Ok(mut w) = enc.write_header() {
                let _ = w.write_image_data(&self.rgba);
            }
        }
        out
    }

    /// Writes a PNG atomically.
    pub fn save_png(&self, path: &std::path::Path) -> Result<(), MeshError> {
        write_atomic(path, &self.encode_png())
    }
}

/// A 3D polyline drawn over the shaded mesh.
#[derive(Clone, Debug)]
pub struct Overlay {
    pub points: Vec<[f64; 3]>,
    pub closed: bool,
    pub colour: [u8; 4],
    /// Drawn on top of everything when false; depth-tested when true.
    pub depth_test: bool,
}

/// Rendering options. Outside the crate, start from
/// [`RenderOptions::default`] and change fields with the `with_*` setters
/// (or by assignment).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct RenderOptions {
    /// Image width in pixels (default 512).
    pub width: usize,
    /// Image height in pixels (default 512).
    pub height: usize,
    /// Camera direction (default front).
    pub view: View,
    /// Background colour (default white).
    pub background: [u8; 4],
    /// One colour per group (default: the GLB palette).
    pub group_colours: Option<Vec<[u8; 3]>>,
    /// Polylines to draw over the mesh (default none).
    pub overlays: Vec<Overlay>,
    /// Fraction of the image left as margin (default 0.05).
    pub margin: f64,
}

setters!(RenderOptions {
    with_width: width: usize,
    with_height: height: usize,
    with_view: view: View,
    with_background: background: [u8; 4],
    with_group_colours: group_colours: Option<Vec<[u8; 3]>>,
    with_overlays: overlays: Vec<Overlay>,
    with_margin: margin: f64,
});

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 512,
            height: 512,
            view: View::Front,
            background: [255, 255, 255, 255],
            group_colours: None,
            overlays: Vec::new(),
            margin: 0.05,
        }
    }
}

/// Renders `m` (shaded, double-sided) with the given options; the camera is
/// fitted to the mesh's bounding box.
pub fn render(m: &Mesh, o: &RenderOptions) -> Image {
    let cam = Camera::fit(m, o.view, o.width, o.height, o.margin);
    render_with_camera(m, o, &cam)
}

/// Renders several views side by side at one common scale (orthographic
/// views share pixels per unit, so front and side compare directly).
pub fn render_views(m: &Mesh, views: &[View], o: &RenderOptions) -> Image {
    let cams: Vec<Camera> = views
        .iter()
        .map(|&v| Camera::fit(m, v, o.width, o.height, o.margin))
        .collect();
    let common = cams
        .iter()
        .zip(views)
        .filter(|(_, v)| !matches!(v, View::Perspective { .. }))
        .map(|(c, _)| c.scale())
        .fold(f64::INFINITY, f64::min);
    let images: Vec<Image> = cams
        .into_iter()
        .zip(views)
        .map(|(c, v)| {
            let c = if matches!(v, View::Perspective { .. }) {
                c
            } else {
                c.with_scale(common)
            };
            render_with_camera(m, o, &c)
        })
        .collect();
    Image::hstack(&images, o.background)
}

/// Renders with an explicit camera (for image series with a fixed frame).
pub fn render_with_camera(m: &Mesh, o: &RenderOptions, cam: &Camera) -> Image {
    let (w, h) = (o.width, o.height);
    let mut img = Image::new(w, h, o.background);
    let mut depth = vec![f64::INFINITY; w * h];
    let screen: Vec<[f64; 3]> = m.positions.iter().map(|&p| cam.project(p)).collect();
    let light = crate::surface::normalize([0.4, 0.6, 1.0]);
    let colour_of = |g: usize| -> [f64; 3] {
        match &o.group_colours {
            Some(c) if !c.is_empty() => {
                let c = c[g % c.len()];
                [
                    c[0] as f64 / 255.0,
                    c[1] as f64 / 255.0,
                    c[2] as f64 / 255.0,
                ]
            }
            _ => {
                let c = crate::mesh::io::group_colour_rgb(g);
                [c[0] as f64, c[1] as f64, c[2] as f64]
            }
        }
    };
    // smooth (per-pixel interpolated vertex normals) where the mesh is
    // smooth, flat across creases: a vertex normal is used only if it is
    // within 45 degrees of the face normal
    let vn: Vec<[f64; 3]> = m
        .vertex_normals()
        .iter()
        .map(|&n| cam.to_view_dir(n))
        .collect();
    for (t, tri) in m.triangles.iter().enumerate() {
        let fnorm = cam.to_view_dir(crate::surface::normalize(m.face_normal_area(t)));
        let corner_normals = tri.map(|i| {
            let n = vn[i as usize];
            if crate::mesh::dot(n, fnorm) > std::f64::consts::FRAC_1_SQRT_2 {
                n
            } else {
                fnorm
            }
        });
        let base = colour_of(m.tri_group[t] as usize);
        let p = [
            screen[tri[0] as usize],
            screen[tri[1] as usize],
            screen[tri[2] as usize],
        ];
        raster_triangle(&mut img, &mut depth, p, |w| {
            let mut n = [0.0; 3];
            for k in 0..3 {
                n[k] = w[0] * corner_normals[0][k]
                    + w[1] * corner_normals[1][k]
                    + w[2] * corner_normals[2][k];
            }
            shade(base, crate::surface::normalize(n), light)
        });
    }
    for ov in &o.overlays {
        let pts: Vec<[f64; 3]> = ov.points.iter().map(|&p| cam.project(p)).collect();
        let n = pts.len();
        let segs = if ov.closed { n } else { n.saturating_sub(1) };
        for i in 0..segs {
            draw_line(
                &mut img,
                &depth,
                pts[i],
                pts[(i + 1) % n],
                ov.colour,
                ov.depth_test,
            );
        }
    }
    img
}

fn edge(a: [f64; 3], b: [f64; 3], x: f64, y: f64) -> f64 {
    (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
}

/// Blinn-Phong shading of a double-sided surface lit from `light` (view
/// space), with the viewer along +z.
fn shade(base: [f64; 3], n: [f64; 3], light: [f64; 3]) -> [u8; 4] {
    // double-sided: flip towards the viewer
    let n = if n[2] < 0.0 { [-n[0], -n[1], -n[2]] } else { n };
    let diffuse = crate::mesh::dot(n, light).max(0.0);
    let half = crate::surface::normalize([light[0], light[1], light[2] + 1.0]);
    let spec = crate::mesh::dot(n, half).max(0.0).powi(32) * 0.25;
    let c = |x: f64| ((x * (0.25 + 0.7 * diffuse) + spec).min(1.0) * 255.0) as u8;
    [c(base[0]), c(base[1]), c(base[2]), 255]
}

fn raster_triangle(
    img: &mut Image,
    depth: &mut [f64],
    p: [[f64; 3]; 3],
    colour: impl Fn([f64; 3]) -> [u8; 4],
) {
    let area = edge(p[0], p[1], p[2][0], p[2][1]);
    if area.abs() < 1e-12 || !area.is_finite() {
        return;
    }
    let Some((lo, hi)) = crate::vec3::bounds(&p) else {
        return;
    };
    let xmin = lo[0].floor().max(0.0) as usize;
    let ymin = lo[1].floor().max(0.0) as usize;
    let xmax = (hi[0].ceil() as i64).min(img.width as i64 - 1);
    let ymax = (hi[1].ceil() as i64).min(img.height as i64 - 1);
    if xmax < 0 || ymax < 0 {
        return;
    }
    for y in ymin..=ymax as usize {
        for x in xmin..=xmax as usize {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let w0 = edge(p[1], p[2], px, py) / area;
            let w1 = edge(p[2], p[0], px, py) / area;
            let w2 = 1.0 - w0 - w1;
            if w0 < 0.0 || w1 < 0.0 || w2 < 0.0 {
                continue;
            }
            let z = w0 * p[0][2] + w1 * p[1][2] + w2 * p[2][2];
            let o = y * img.width + x;
            if z < depth[o] {
                depth[o] = z;
                img.put(x as i64, y as i64, colour([w0, w1, w2]));
            }
        }
    }
}

fn draw_line(img: &mut Image, depth: &[f64], a: [f64; 3], b: [f64; 3], col: [u8; 4], test: bool) {
    let steps = ((b[0] - a[0]).abs().max((b[1] - a[1]).abs()).ceil() as usize).clamp(1, 100_000);
    for s in 0..=steps {
        let t = s as f64 / steps as f64;
        let (x, y, z) = (
            a[0] + t * (b[0] - a[0]),
            a[1] + t * (b[1] - a[1]),
            a[2] + t * (b[2] - a[2]),
        );
        for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (xi, yi) = (x.floor() as i64 + dx, y.floor() as i64 + dy);
            if xi < 0 || yi < 0 || xi as usize >= img.width || yi as usize >= img.height {
                continue;
            }
            let o = yi as usize * img.width + xi as usize;
            if !test || z <= depth[o] + 1e-3 * depth[o].abs().max(1.0) {
                img.put(xi, yi, col);
            }
        }
    }
}
