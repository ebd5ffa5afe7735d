//! Reading the sections JSON of `pde6 patch`, building a chain by method and
//! the `pde6 mode` evaluation (library side of `src/cli/pde6.rs`).

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
    let text = crate::mesh::io::read_input_text(path, "sections file").map_err(|source| {
        Pde6Error::Read {
            what: what.clone(),
            source,
        }
    })?;
    let f: SectionFile = serde_json::from_str(&text).map_err(|source| Pde6Error::Parse {
        what: what.clone(),
        source,
    })?;
    f.sections
        .into_iter()
        .enumerate()
        .map(|(i, s)| {
            let bad = |e: Pde6Error| e.in_section(format!("{what}: section {i}"));
            let curve = match (s.gec, s.fourier) {
                (Some(g), None) => {
                    let g = Gec::new(g.frame, g.centre, g.x, g.y).map_err(|e| bad(e.into()))?;
                    crate::curve::gec::input::check_magnitudes(&g).map_err(|e| bad(e.into()))?;
                    g.to_fourier3()
                }
                (None, Some(f)) => f,
                _ => {
                    return Err(bad(Pde6Error::Input(
                        "give exactly one of \"gec\" or \"fourier\"".into(),
                    )))
                }
            };
            limits::check(
                "harmonics",
                curve.cos.len().max(curve.sin.len()),
                limits::CURVE_HARMONICS,
            )
            .map_err(|e| bad(e.into()))?;
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

/// `pde6 mode`: the single-harmonic function through six values at
/// u = 0, 0.2, ..., 1, evaluated at `at`: (JSON, one-line summary).
pub fn mode_at(
    a: f64,
    n: usize,
    values: &[f64],
    at: f64,
) -> Result<(serde_json::Value, String), Pde6Error> {
    use super::{Mode, ModeSolver};
    use crate::jet::Jet;
    if values.len() != 6 {
        return Err(Pde6Error::Input(format!(
            "--values needs six comma-separated numbers, got {}",
            values.len()
        )));
    }
    if !(0.0..=1.0).contains(&at) {
        return Err(Pde6Error::Input(format!(
            "--at {at}: must lie in [0, 1] (the six values sit at u = 0, 0.2, ..., 1)"
        )));
    }
    limits::check("--n", n, limits::CURVE_HARMONICS)?;
    let v: [f64; 6] = std::array::from_fn(|i| values[i]);
    let m = Mode::interpolate(a, n, v)?;
    let j = m.eval(Jet::<3, 1>::var_u(at));
    let cond = ModeSolver::new(
        m.basis,
        super::mode::method1_conditions(super::mode::NODES_METHOD1),
    )?
    .condition_number;
    let vals = [j.deriv(0, 0), j.deriv(1, 0), j.deriv(2, 0), cond];
    if vals.iter().chain(&m.coef).any(|x| !x.is_finite()) {
        return Err(Pde6Error::Input(format!("A_{n}({at}) with --a {a} is not finite in double precision (the basis overflows; reduce --n or |--a|)")));
    }
    let out = serde_json::json!({
        "a": a, "n": n, "regime": format!("{:?}", m.basis.regime), "q": m.basis.q,
        "at": at, "value": j.deriv(0, 0), "slope": j.deriv(1, 0), "curvature": j.deriv(2, 0),
        "coefficients": m.coef, "condition_number": cond,
    });
    let line = format!(
        "A_{n}({at}) = {:.15e}  A' = {:.6e}  A'' = {:.6e}  ({:?}, q = {:.6}, condition {:.3e})",
        j.deriv(0, 0),
        j.deriv(1, 0),
        j.deriv(2, 0),
        m.basis.regime,
        m.basis.q,
        cond
    );
    Ok((out, line))
}

/// `pde6 patch`: (JSON summary without the unit, one-line summary).
pub fn patch_summary(
    chain: &Chain,
    sections: usize,
    mesh: &crate::mesh::Mesh,
    a: f64,
    output: &Path,
) -> (serde_json::Value, String) {
    let jumps = crate::surface::Joined::join_jumps(chain, super::JOIN_SAMPLES);
    let json = serde_json::json!({
        "sections": sections, "pieces": chain.pieces.len(), "method": format!("{:?}", chain.method),
        "a": a, "max_condition": chain.max_condition(), "coefficients": chain.coefficient_count(),
        "join_jumps_c0_c1_c2": jumps, "vertices": mesh.positions.len(), "triangles": mesh.triangles.len(),
        "output": output.display().to_string(),
    });
    let line = format!(
        "wrote {} ({} sections, {} pieces, {:?}, a = {a}): {} triangles, worst condition {:.3e}, join jumps C0/C1/C2 {:.2e} {:.2e} {:.2e}",
        output.display(),
        sections,
        chain.pieces.len(),
        chain.method,
        mesh.triangles.len(),
        chain.max_condition(),
        jumps[0],
        jumps[1],
        jumps[2]
    );
    (json, line)
}
