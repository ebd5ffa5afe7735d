//! The parameters of [`super::figure`]'s humanoid and their ranges.

/// A standing humanoid's pose and proportions. Lengths are fractions of the
/// height except [`Humanoid::height`] (model units).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Humanoid {
    /// Total height, model units (metres when written as a drawing).
    pub height: f64,
    /// Head height (chin to crown).
    pub head: f64,
    /// Head width / head height.
    pub head_aspect: f64,
    /// Half width at the shoulders.
    pub shoulder: f64,
    /// Half width at the waist.
    pub waist: f64,
    /// Half width at the hips.
    pub hip: f64,
    /// Neck radius.
    pub neck: f64,
    /// Arm angles below the horizontal, degrees (left arm, right arm): 0 is
    /// a T-pose.
    pub arm_angle_deg: [f64; 2],
    /// Shoulder to wrist.
    pub arm_length: f64,
    /// Upper-arm radius (the wrist is 0.55 of it).
    pub arm_radius: f64,
    /// Gap between the legs' shapes at the knee (the drawn gap is about
    /// this less half the figure's blend, 0.012: see `figure::smin`).
    pub leg_gap: f64,
    /// How far the ankles are out beyond the knees (a wide stance).
    pub stance: f64,
    /// Crotch height.
    pub crotch: f64,
    /// Thigh radius.
    pub leg_radius: f64,
    /// Half depth of the torso (side view).
    pub depth: f64,
    /// How far the belly bulges forward (side view).
    pub belly: f64,
}

impl Default for Humanoid {
    /// An average adult, arms 60 degrees below horizontal.
    fn default() -> Humanoid {
        Humanoid {
            height: 1.0,
            head: 0.13,
            head_aspect: 0.75,
            shoulder: 0.125,
            waist: 0.085,
            hip: 0.1,
            neck: 0.028,
            arm_angle_deg: [60.0, 60.0],
            arm_length: 0.36,
            arm_radius: 0.03,
            leg_gap: 0.03,
            stance: 0.0,
            crotch: 0.47,
            leg_radius: 0.05,
            depth: 0.065,
            belly: 0.0,
        }
    }
}

/// Inclusive ranges `[lo, hi]` of every proportion (the pose's two angles
/// share one range; `arm_spread` is the largest difference between them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HumanoidRanges {
    pub head: [f64; 2],
    pub head_aspect: [f64; 2],
    pub shoulder: [f64; 2],
    pub waist_of_shoulder: [f64; 2],
    pub hip_of_shoulder: [f64; 2],
    pub neck_of_head: [f64; 2],
    pub arm_angle_deg: [f64; 2],
    pub arm_spread_deg: f64,
    pub arm_length: [f64; 2],
    pub arm_radius: [f64; 2],
    pub leg_gap: [f64; 2],
    pub stance: [f64; 2],
    pub crotch: [f64; 2],
    pub leg_radius: [f64; 2],
    pub depth: [f64; 2],
    pub belly: [f64; 2],
}

impl HumanoidRanges {
    /// Issue 28 item 3: arms from horizontal to 75 degrees below, up to 30
    /// degrees apart; legs from nearly touching (a drawn gap of 1 % of the
    /// height) to wide; heads 1/8 to 1/2 of the height; short or long legs;
    /// chubby, broad or thin-armed.
    pub const ISSUE: HumanoidRanges = HumanoidRanges {
        head: [0.125, 0.5],
        head_aspect: [0.6, 0.95],
        shoulder: [0.09, 0.17],
        waist_of_shoulder: [0.55, 1.0],
        hip_of_shoulder: [0.65, 1.0],
        neck_of_head: [0.15, 0.3],
        arm_angle_deg: [0.0, 75.0],
        arm_spread_deg: 30.0,
        arm_length: [0.3, 0.42],
        arm_radius: [0.018, 0.045],
        leg_gap: [0.016, 0.12],
        stance: [0.0, 0.06],
        crotch: [0.36, 0.55],
        leg_radius: [0.035, 0.075],
        depth: [0.045, 0.1],
        belly: [0.0, 0.04],
    };

    /// Wider than [`Self::ISSUE`] on every side it can be (the corpus's
    /// family, so the pipeline meets drawings outside the ranges it must
    /// build).
    pub const WIDE: HumanoidRanges = HumanoidRanges {
        head: [0.11, 0.52],
        head_aspect: [0.55, 1.0],
        shoulder: [0.08, 0.19],
        waist_of_shoulder: [0.5, 1.05],
        hip_of_shoulder: [0.6, 1.05],
        neck_of_head: [0.13, 0.33],
        arm_angle_deg: [-5.0, 78.0],
        arm_spread_deg: 35.0,
        arm_length: [0.28, 0.45],
        arm_radius: [0.016, 0.05],
        leg_gap: [0.016, 0.15],
        stance: [0.0, 0.08],
        crotch: [0.33, 0.58],
        leg_radius: [0.03, 0.08],
        depth: [0.04, 0.11],
        belly: [0.0, 0.05],
    };

    /// The humanoid at the point `u` of the unit cube (16 coordinates in
    /// [0, 1], in the order of the fields; `u[7]` and `u[8]` give the two
    /// arm angles, the second within the spread of the first), `height`
    /// model units tall.
    pub fn at(&self, u: &[f64; 16], height: f64) -> Humanoid {
        let l = |r: [f64; 2], t: f64| r[0] + t.clamp(0.0, 1.0) * (r[1] - r[0]);
        let head = l(self.head, u[0]);
        let shoulder = l(self.shoulder, u[2]);
        let a0 = l(self.arm_angle_deg, u[6]);
        let lo = (a0 - self.arm_spread_deg).max(self.arm_angle_deg[0]);
        let hi = (a0 + self.arm_spread_deg).min(self.arm_angle_deg[1]);
        let a1 = l([lo, hi], u[7]);
        Humanoid {
            height,
            head,
            head_aspect: l(self.head_aspect, u[1]),
            shoulder,
            waist: shoulder * l(self.waist_of_shoulder, u[3]),
            hip: shoulder * l(self.hip_of_shoulder, u[4]),
            neck: head * l(self.neck_of_head, u[5]),
            arm_angle_deg: [a0, a1],
            arm_length: l(self.arm_length, u[8]),
            arm_radius: l(self.arm_radius, u[9]),
            leg_gap: l(self.leg_gap, u[10]),
            stance: l(self.stance, u[11]),
            // the torso keeps `figure::MIN_TORSO` below the shoulders
            crotch: l(self.crotch, u[12]).min(1.0 - head - (0.35 * head).min(0.06) - MIN_TORSO),
            leg_radius: l(self.leg_radius, u[13]),
            depth: l(self.depth, u[14]),
            belly: l(self.belly, u[15]),
        }
    }
}

/// Shortest torso (crotch to shoulders), a fraction of the height.
pub const MIN_TORSO: f64 = 0.12;
