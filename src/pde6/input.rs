//! Reading the sections JSON of `pde6 patch`, building a chain by method, and
//! the text summary of the open-parts body (library side of `src/cli/pde6.rs`).

use super::body::BodyReport;
use super::{Chain, Method, Pde6Error, Section};
use crate::curve::gec::Gec;
use crate::curve::Fourier3;
use crate::limits;
use std::path::Path;

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SectionFile {
    sections: Vec<SectionEntry>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SectionEntry {
    u: f64,
    gec: Option<Gec>,
    fourier: Option<Fourier3>,
}

/// Reads a sections JSON: `{"sections": [{"u": .., "gec"|"fourier": ..}, ..]}`.
pub fn read_sections(path: &Path) -> Result<Vec<Section>, Pde6Error> {
    let what = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| Pde6Error::Input(format!("reading {what}: {e}")))?;
    let f: SectionFile = serde_json::from_str(&text)
        .map_err(|e| Pde6Error::Input(format!("parsing {what}: {e}")))?;
    f.sections
        .into_iter()
        .enumerate()
        .map(|(i, s)| {
            let bad =
                |e: &dyn std::fmt::Display| Pde6Error::Input(format!("{what}: section {i}: {e}"));
            let curve = match (s.gec, s.fourier) {
                (Some(g), None) => {
                    let g = Gec::new(g.frame, g.centre, g.x, g.y).map_err(|e| bad(&e))?;
                    crate::curve::gec::input::check_magnitudes(&g).map_err(|e| bad(&e))?;
                    g.to_fourier3()
                }
                (None, Some(f)) => f,
                _ => return Err(bad(&"give exactly one of \"gec\" or \"fourier\"")),
            };
            limits::check(
                "harmonics",
                curve.cos.len().max(curve.sin.len()),
                limits::CURVE_HARMONICS,
            )
            .map_err(|e| bad(&e))?;
            Ok(Section { u: s.u, curve })
        })
        .collect()
}

/// The chain of `method` through `sections` (`first`: method 1 and 2).
pub fn build_chain(
    a: f64,
    method: Method,
    sections: &[Section],
    first: usize,
) -> Result<Chain, Pde6Error> {
    match method {
        Method::GlobalC2 => Chain::c2_global(a, sections),
        Method::SharedCurves => Chain::method1(a, sections, first),
        Method::CarriedDerivatives => Chain::method2(a, sections, first),
    }
}

/// Text summary of the open-parts reconstruction (percent of the height).
pub fn open_parts_summary(report: &BodyReport, output: &Path) -> String {
    let h = 100.0;
    let mut s = format!(
        "wrote {} ({} triangles); body height {:.3}\n  reconstruction -> skin: RMS {:.3} %, max {:.3} % of the height\n  skin -> reconstruction: RMS {:.3} %, max {:.3} %\n",
        output.display(),
        report.recon_triangles,
        report.body_height,
        h * report.recon_to_skin_rms_rel,
        h * report.recon_to_skin_max_rel,
        h * report.skin_to_recon_rms_rel,
        h * report.skin_to_recon_max_rel
    );
    for p in &report.parts {
        s.push_str(&format!(
            "  {:<15} RMS {:.3} % max {:.3} %  roughness u {:.4} v {:.4}  slip {:.2} deg\n",
            p.name,
            h * p.recon_to_skin_rms_rel,
            h * p.recon_to_skin_max_rel,
            p.roughness.u,
            p.roughness.v,
            p.slip_deg
        ));
    }
    s
}
