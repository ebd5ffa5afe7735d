//! MakeHuman's expression units (CC0, `data/makehuman/targets/expression/`,
//! embedded) and the map from FACS action units to them chosen here.
//!
//! | AU | FACS name | MakeHuman units (weight 1 each) |
//! |---|---|---|
//! | AU1 | inner brow raiser | eyebrows-left-inner-up, eyebrows-right-inner-up |
//! | AU2 | outer brow raiser | eyebrows-left-extern-up, eyebrows-right-extern-up |
//! | AU4 | brow lowerer | eyebrows-left-down, eyebrows-right-down |
//! | AU5 | upper lid raiser | eye-left-opened-up, eye-right-opened-up |
//! | AU7 | lid tightener | eye-left-slit, eye-right-slit |
//! | AU9 | nose wrinkler | nose-left-elevation, nose-right-elevation |
//! | AU10 | upper lip raiser | mouth-elevation |
//! | AU12 | lip corner puller | mouth-corner-puller |
//! | AU13 | sharp lip puller | mouth-upward-retraction |
//! | AU15 | lip corner depressor | mouth-depression |
//! | AU18 | lip pucker | mouth-protusion |
//! | AU20 | lip stretcher | mouth-retraction |
//! | AU21 | neck tightener | neck-platysma |
//! | AU22 | lip funneler | mouth-eversion |
//! | AU24 | lip pressor | mouth-compression |
//! | AU25 | lips part | mouth-parling |
//! | AU38 | nostril dilator | nose-left-dilatation, nose-right-dilatation |
//! | AU43R | eyes closed (right; the set has no left closure) | eye-right-closure |
//!
//! The map follows the FACS definitions of the muscles' visible actions
//! (Ekman, Friesen, Hager 2002) against the units' names and motion; the
//! units with no single AU (eyebrows-*-up = AU1+AU2, mouth-depression-retraction
//! = AU15+AU20, mouth-part-later, nose-depression) are reachable by their
//! own names. Fig 13's table uses [`TABLE_UNITS`].

use super::FaceError;
use crate::makehuman::{parse_target, Target};
use std::io::Read;

/// The embedded expression units: `(name, gzip bytes)`.
pub const UNITS: &[(&str, &[u8])] = &[
    (
        "eye-left-opened-up",
        include_bytes!("../../data/makehuman/targets/expression/eye-left-opened-up.target.gz"),
    ),
    (
        "eye-left-slit",
        include_bytes!("../../data/makehuman/targets/expression/eye-left-slit.target.gz"),
    ),
    (
        "eye-right-closure",
        include_bytes!("../../data/makehuman/targets/expression/eye-right-closure.target.gz"),
    ),
    (
        "eye-right-opened-up",
        include_bytes!("../../data/makehuman/targets/expression/eye-right-opened-up.target.gz"),
    ),
    (
        "eye-right-slit",
        include_bytes!("../../data/makehuman/targets/expression/eye-right-slit.target.gz"),
    ),
    (
        "eyebrows-left-down",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-left-down.target.gz"),
    ),
    (
        "eyebrows-left-extern-up",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-left-extern-up.target.gz"),
    ),
    (
        "eyebrows-left-inner-up",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-left-inner-up.target.gz"),
    ),
    (
        "eyebrows-left-up",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-left-up.target.gz"),
    ),
    (
        "eyebrows-right-down",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-right-down.target.gz"),
    ),
    (
        "eyebrows-right-extern-up",
        include_bytes!(
            "../../data/makehuman/targets/expression/eyebrows-right-extern-up.target.gz"
        ),
    ),
    (
        "eyebrows-right-inner-up",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-right-inner-up.target.gz"),
    ),
    (
        "eyebrows-right-up",
        include_bytes!("../../data/makehuman/targets/expression/eyebrows-right-up.target.gz"),
    ),
    (
        "mouth-compression",
        include_bytes!("../../data/makehuman/targets/expression/mouth-compression.target.gz"),
    ),
    (
        "mouth-corner-puller",
        include_bytes!("../../data/makehuman/targets/expression/mouth-corner-puller.target.gz"),
    ),
    (
        "mouth-depression",
        include_bytes!("../../data/makehuman/targets/expression/mouth-depression.target.gz"),
    ),
    (
        "mouth-depression-retraction",
        include_bytes!(
            "../../data/makehuman/targets/expression/mouth-depression-retraction.target.gz"
        ),
    ),
    (
        "mouth-elevation",
        include_bytes!("../../data/makehuman/targets/expression/mouth-elevation.target.gz"),
    ),
    (
        "mouth-eversion",
        include_bytes!("../../data/makehuman/targets/expression/mouth-eversion.target.gz"),
    ),
    (
        "mouth-parling",
        include_bytes!("../../data/makehuman/targets/expression/mouth-parling.target.gz"),
    ),
    (
        "mouth-part-later",
        include_bytes!("../../data/makehuman/targets/expression/mouth-part-later.target.gz"),
    ),
    (
        "mouth-protusion",
        include_bytes!("../../data/makehuman/targets/expression/mouth-protusion.target.gz"),
    ),
    (
        "mouth-retraction",
        include_bytes!("../../data/makehuman/targets/expression/mouth-retraction.target.gz"),
    ),
    (
        "mouth-upward-retraction",
        include_bytes!("../../data/makehuman/targets/expression/mouth-upward-retraction.target.gz"),
    ),
    (
        "neck-platysma",
        include_bytes!("../../data/makehuman/targets/expression/neck-platysma.target.gz"),
    ),
    (
        "nose-depression",
        include_bytes!("../../data/makehuman/targets/expression/nose-depression.target.gz"),
    ),
    (
        "nose-left-dilatation",
        include_bytes!("../../data/makehuman/targets/expression/nose-left-dilatation.target.gz"),
    ),
    (
        "nose-left-elevation",
        include_bytes!("../../data/makehuman/targets/expression/nose-left-elevation.target.gz"),
    ),
    (
        "nose-right-dilatation",
        include_bytes!("../../data/makehuman/targets/expression/nose-right-dilatation.target.gz"),
    ),
    (
        "nose-right-elevation",
        include_bytes!("../../data/makehuman/targets/expression/nose-right-elevation.target.gz"),
    ),
];

/// A FACS action unit and the MakeHuman units it is made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct FacsUnit {
    pub au: &'static str,
    pub name: &'static str,
    pub units: &'static [&'static str],
}

/// The FACS map of the module doc.
pub const FACS: &[FacsUnit] = &[
    FacsUnit {
        au: "AU1",
        name: "inner brow raiser",
        units: &["eyebrows-left-inner-up", "eyebrows-right-inner-up"],
    },
    FacsUnit {
        au: "AU2",
        name: "outer brow raiser",
        units: &["eyebrows-left-extern-up", "eyebrows-right-extern-up"],
    },
    FacsUnit {
        au: "AU4",
        name: "brow lowerer",
        units: &["eyebrows-left-down", "eyebrows-right-down"],
    },
    FacsUnit {
        au: "AU5",
        name: "upper lid raiser",
        units: &["eye-left-opened-up", "eye-right-opened-up"],
    },
    FacsUnit {
        au: "AU7",
        name: "lid tightener",
        units: &["eye-left-slit", "eye-right-slit"],
    },
    FacsUnit {
        au: "AU9",
        name: "nose wrinkler",
        units: &["nose-left-elevation", "nose-right-elevation"],
    },
    FacsUnit {
        au: "AU10",
        name: "upper lip raiser",
        units: &["mouth-elevation"],
    },
    FacsUnit {
        au: "AU12",
        name: "lip corner puller",
        units: &["mouth-corner-puller"],
    },
    FacsUnit {
        au: "AU13",
        name: "sharp lip puller",
        units: &["mouth-upward-retraction"],
    },
    FacsUnit {
        au: "AU15",
        name: "lip corner depressor",
        units: &["mouth-depression"],
    },
    FacsUnit {
        au: "AU18",
        name: "lip pucker",
        units: &["mouth-protusion"],
    },
    FacsUnit {
        au: "AU20",
        name: "lip stretcher",
        units: &["mouth-retraction"],
    },
    FacsUnit {
        au: "AU21",
        name: "neck tightener",
        units: &["neck-platysma"],
    },
    FacsUnit {
        au: "AU22",
        name: "lip funneler",
        units: &["mouth-eversion"],
    },
    FacsUnit {
        au: "AU24",
        name: "lip pressor",
        units: &["mouth-compression"],
    },
    FacsUnit {
        au: "AU25",
        name: "lips part",
        units: &["mouth-parling"],
    },
    FacsUnit {
        au: "AU38",
        name: "nostril dilator",
        units: &["nose-left-dilatation", "nose-right-dilatation"],
    },
    FacsUnit {
        au: "AU43R",
        name: "eyes closed (right)",
        units: &["eye-right-closure"],
    },
];

/// The action units of the Fig 13 table (the paper's AU1, AU2, AU4, AU9,
/// and AU12): the units this work was developed and measured on; every
/// other unit is held out.
pub const TABLE_UNITS: &[&str] = &["AU1", "AU2", "AU4", "AU9", "AU12"];

/// The FACS map.
pub fn facs_units() -> &'static [FacsUnit] {
    FACS
}

/// One embedded unit by MakeHuman name.
pub fn unit_target(name: &str) -> Option<Result<Target, FaceError>> {
    let (_, bytes) = UNITS.iter().find(|(n, _)| *n == name)?;
    let mut s = String::new();
    let read = flate2::read::GzDecoder::new(*bytes).read_to_string(&mut s);
    Some(
        read.map_err(|source| FaceError::Expression {
            name: name.into(),
            source,
        })
        .and_then(|_| parse_target(name, &s).map_err(FaceError::from)),
    )
}

/// The targets of an expression named by AU (`AU12`, any case) or by
/// MakeHuman unit name, each with weight `w`.
pub fn expression(name: &str, w: f64) -> Result<Vec<(Target, f64)>, FaceError> {
    if !w.is_finite() || w.abs() > crate::makehuman::MORPH_WEIGHT_MAX {
        return Err(FaceError::Weight {
            name: name.to_string(),
            weight: w,
        });
    }
    let units: Vec<&str> = match FACS.iter().find(|f| f.au.eq_ignore_ascii_case(name)) {
        Some(f) => f.units.to_vec(),
        None => vec![name],
    };
    units
        .into_iter()
        .map(|u| match unit_target(u) {
            Some(t) => t.map(|t| (t, w)),
            None => Err(FaceError::UnknownExpression {
                name: name.to_string(),
                known: known_names(),
            }),
        })
        .collect()
}

/// Every accepted name, for error messages and `--help`.
pub fn known_names() -> String {
    let aus: Vec<&str> = FACS.iter().map(|f| f.au).collect();
    let units: Vec<&str> = UNITS.iter().map(|(n, _)| *n).collect();
    format!("{} or a unit: {}", aus.join(", "), units.join(", "))
}

/// `positions` moved by `targets` (vertex indices of the full base mesh).
pub fn apply(positions: &mut [[f64; 3]], targets: &[(Target, f64)]) -> Result<(), FaceError> {
    for (t, w) in targets {
        for &(i, d) in &t.offsets {
            let p = positions.get_mut(i as usize).ok_or_else(|| {
                FaceError::Template(format!(
                    "expression {} moves vertex {i}, which does not exist",
                    t.name
                ))
            })?;
            for k in 0..3 {
                p[k] += w * d[k];
            }
        }
    }
    Ok(())
}
