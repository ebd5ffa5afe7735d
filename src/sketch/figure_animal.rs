//! A parametric four-legged animal for the corpus ([`super::figure`]):
//! its lateral silhouette (the "front" file of a quadruped, model x-y, head
//! toward +x) and its head-on view (the "side" file, model z-y).

use super::figure::{Figure, Shape, GRID_ROWS};

/// Where the tail points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Tail {
    Up,
    Down,
    None,
}

/// A four-legged animal. Lengths are fractions of the body length except
/// [`Quadruped::length`] (model units, nose to tail base, roughly).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Quadruped {
    pub length: f64,
    /// Body half height (belly to back over 2).
    pub body: f64,
    /// Body half width (head-on view).
    pub width: f64,
    /// Ground to belly.
    pub legs: f64,
    /// Leg radius at the top, front and back (the foot is 0.6 of it).
    pub leg_radius: [f64; 2],
    /// Back legs' length relative to the front legs' (unequal legs).
    pub back_leg_scale: f64,
    /// 4: the legs of each pair drawn apart (a walking pose); 2: one leg
    /// per pair visible.
    pub visible_legs: u8,
    /// Neck length and its angle above the horizontal (degrees).
    pub neck: f64,
    pub neck_angle_deg: f64,
    /// Head half length.
    pub head: f64,
    pub tail: Tail,
    /// An elephant's trunk hanging from the head.
    pub trunk: bool,
}

/// The figures' blend radius, as a fraction of the animal's length.
const BLEND: f64 = 0.02;

impl Quadruped {
    /// A dog.
    pub fn dog() -> Quadruped {
        Quadruped {
            length: 0.8,
            body: 0.14,
            width: 0.11,
            legs: 0.3,
            leg_radius: [0.04, 0.045],
            back_leg_scale: 1.0,
            visible_legs: 4,
            neck: 0.18,
            neck_angle_deg: 55.0,
            head: 0.1,
            tail: Tail::Up,
            trunk: false,
        }
    }

    /// The lateral and head-on figures, feet at y = 0.
    pub fn figures(&self) -> (Figure, Figure) {
        let (lat, neck_top, head_y) = self.lateral();
        (lat, self.head_on(neck_top, head_y))
    }

    /// The lateral figure, the height of its neck's top and its head's
    /// centre (the head-on view's neck and head sit at those heights).
    fn lateral(&self) -> (Figure, f64, f64) {
        let s = |v: f64| v * self.length;
        let yb = self.legs + self.body;
        let half = 0.5 - self.body;
        let mut lat = Figure {
            blend: s(BLEND),
            ..Figure::default()
        };
        lat.shapes.push(Shape::Capsule {
            a: [s(-half), s(yb)],
            b: [s(half), s(yb)],
            ra: s(self.body),
            rb: s(self.body),
        });
        self.lateral_legs(&mut lat);
        let (sa, ca) = self.neck_angle_deg.to_radians().sin_cos();
        let n0 = [half + 0.2 * self.body, yb + 0.3 * self.body];
        let n1 = [n0[0] + self.neck * ca, n0[1] + self.neck * sa];
        lat.shapes.push(Shape::Capsule {
            a: [s(n0[0]), s(n0[1])],
            b: [s(n1[0]), s(n1[1])],
            ra: s(0.55 * self.body),
            rb: s(0.4 * self.body),
        });
        let hc = [n1[0] + 0.6 * self.head, n1[1]];
        lat.shapes.push(Shape::Ellipse {
            c: [s(hc[0]), s(hc[1])],
            r: [s(self.head), s(0.55 * self.head)],
            turn: -0.3,
        });
        if self.trunk {
            let t0 = [hc[0] + 0.8 * self.head, hc[1] - 0.2 * self.head];
            lat.shapes.push(Shape::Capsule {
                a: [s(t0[0]), s(t0[1])],
                b: [s(t0[0] + 0.05), s(0.35 * self.legs)],
                ra: s(0.3 * self.head),
                rb: s(0.12 * self.head),
            });
        }
        let tail_deg = match self.tail {
            Tail::Up => Some(40.0f64),
            Tail::Down => Some(-65.0),
            Tail::None => None,
        };
        if let Some(deg) = tail_deg {
            let (st, ct) = deg.to_radians().sin_cos();
            let t0 = [-half - 0.6 * self.body, yb + 0.5 * self.body];
            let len = 0.3;
            lat.shapes.push(Shape::Capsule {
                a: [s(t0[0]), s(t0[1])],
                b: [s(t0[0] - len * ct), s(t0[1] + len * st)],
                ra: s(0.04),
                rb: s(0.015),
            });
        }
        (lat, n1[1], hc[1])
    }

    /// The lateral view's legs: front and back, each one capsule, or two
    /// side by side (stepping apart) when four legs are visible.
    fn lateral_legs(&self, lat: &mut Figure) {
        let s = |v: f64| v * self.length;
        let half = 0.5 - self.body;
        for (k, x) in [
            (0usize, half - 0.3 * self.body),
            (1, -half + 0.3 * self.body),
        ] {
            let r = self.leg_radius[k];
            let len = if k == 1 { self.back_leg_scale } else { 1.0 };
            let top = self.legs * len + 0.5 * self.body;
            let xs: Vec<f64> = if self.visible_legs == 4 {
                vec![x - 1.3 * r, x + 1.3 * r]
            } else {
                vec![x]
            };
            for (j, &xl) in xs.iter().enumerate() {
                let step = if xs.len() == 2 {
                    (j as f64 - 0.5) * 2.0 * r
                } else {
                    0.0
                };
                lat.shapes.push(Shape::Capsule {
                    a: [s(xl), s(top)],
                    b: [s(xl + step), s(0.6 * r)],
                    ra: s(r),
                    rb: s(0.6 * r),
                });
            }
        }
    }

    /// Head-on: body, legs apart in z, the neck up to `neck_top` and the
    /// head centred at `head_y` (the lateral view's heights).
    fn head_on(&self, neck_top: f64, head_y: f64) -> Figure {
        let s = |v: f64| v * self.length;
        let yb = self.legs + self.body;
        let mut on = Figure {
            blend: s(BLEND),
            ..Figure::default()
        };
        on.shapes.push(Shape::Ellipse {
            c: [0.0, s(yb)],
            r: [s(self.width), s(self.body)],
            turn: 0.0,
        });
        let r = self.leg_radius[0];
        for side in [-1.0, 1.0] {
            let z = side * (self.width - r);
            on.shapes.push(Shape::Capsule {
                a: [s(z), s(self.legs + 0.5 * self.body)],
                b: [s(z), s(0.6 * r)],
                ra: s(r),
                rb: s(0.6 * r),
            });
        }
        on.shapes.push(Shape::Capsule {
            a: [0.0, s(yb)],
            b: [0.0, s(neck_top)],
            ra: s(0.5 * self.body),
            rb: s(0.4 * self.body),
        });
        on.shapes.push(Shape::Ellipse {
            c: [0.0, s(head_y)],
            r: [s(0.55 * self.head), s(0.55 * self.head)],
            turn: 0.0,
        });
        if self.trunk {
            on.shapes.push(Shape::Capsule {
                a: [0.0, s(head_y)],
                b: [0.0, s(0.35 * self.legs)],
                ra: s(0.3 * self.head),
                rb: s(0.12 * self.head),
            });
        }
        on
    }

    /// The traced lateral and head-on outlines.
    pub fn outlines(&self) -> Option<super::figure::OutlinePair> {
        let (l, o) = self.figures();
        let s = self.length;
        let top = (self.legs + 2.0 * self.body + self.neck + self.head + 0.1) * s;
        let lat = l.outline([-0.9 * s, -0.02 * s], [0.9 * s, top], GRID_ROWS)?;
        let on = o.outline([-0.5 * s, -0.02 * s], [0.5 * s, top], GRID_ROWS)?;
        Some((lat, on))
    }
}
