//! The verification layer: the list of every equation family and its
//! checks, above the families (the `check` module below them holds only the
//! report types, kinds and named tolerances).
//!
//! A new family adds one line to [`families`] (its `checks` generator).

use crate::check::{Check, Kind};

/// One equation family and its check generator.
pub struct Family {
    pub name: &'static str,
    /// Papers it implements (file numbers).
    pub papers: &'static str,
    pub checks: fn() -> Vec<Check>,
}

impl Family {
    /// The family's checks, each loose tolerance measured at rounding level
    /// given its reason ([`Check::with_loose_reason`]).
    pub fn run(&self) -> Vec<Check> {
        (self.checks)()
            .into_iter()
            .map(Check::with_loose_reason)
            .collect()
    }
}

/// Every family, in dependency order.
#[rustfmt::skip]
pub fn families() -> &'static [Family] {
    &[
        Family { name: "jet", papers: "-", checks: crate::jet::check::checks },
        Family { name: "mesh", papers: "-", checks: crate::mesh::check::checks },
        Family { name: "surface", papers: "-", checks: crate::surface::check::checks },
        Family { name: "gec", papers: "000, 002", checks: crate::curve::gec::check::checks },
        Family { name: "pde4", papers: "000", checks: crate::pde4::check::checks },
        Family { name: "plate", papers: "001", checks: crate::plate::check::checks },
        Family { name: "pde6", papers: "002", checks: crate::pde6::check::checks },
        Family { name: "ode6", papers: "004", checks: crate::ode6::check::checks },
        Family { name: "conv", papers: "003", checks: crate::conv::check::checks },
        Family { name: "profile", papers: "000", checks: crate::profile::check::checks },
        Family { name: "sketch", papers: "000", checks: crate::sketch::check::checks },
        Family { name: "template", papers: "000", checks: crate::template::check::checks },
        Family { name: "edit", papers: "000, 001", checks: crate::edit::check::checks },
        Family { name: "sasm", papers: "000", checks: crate::sasm::check::checks },
        Family { name: "body", papers: "002, 000", checks: crate::body::check::checks },
        Family { name: "face", papers: "004", checks: crate::face::check::checks },
        Family { name: "derivatives", papers: "-", checks: derivative_checks },
    ]
}

/// Runs the checks of every family whose name equals `family` (all when
/// `None`). Families run in parallel threads; the order of the result is the
/// registry order.
pub fn run(family: Option<&str>) -> Vec<Check> {
    let names: Vec<&str> = family.into_iter().collect();
    run_timed(&names).0
}

/// Runs the checks of the families named in `names` (all when empty), in
/// parallel threads, and returns them in registry order with each family's
/// wall time in seconds (measured on its own thread; `verify --timings`).
pub fn run_timed(names: &[&str]) -> (Vec<Check>, Vec<(&'static str, f64)>) {
    let selected: Vec<&Family> = families()
        .iter()
        .filter(|f| names.is_empty() || names.contains(&f.name))
        .collect();
    std::thread::scope(|s| {
        let handles: Vec<_> = selected
            .iter()
            .map(|f| {
                s.spawn(move || {
                    let t0 = std::time::Instant::now();
                    let c = f.run();
                    (c, t0.elapsed().as_secs_f64())
                })
            })
            .collect();
        let mut checks = Vec::new();
        let mut times = Vec::new();
        for (h, f) in handles.into_iter().zip(&selected) {
            let (c, t) = h.join().unwrap_or_else(|_| {
                let c = Check::new(
                    f.name,
                    f.papers,
                    "-",
                    &format!("{}.checks-panicked", f.name),
                    Kind::Reference,
                    f64::NAN,
                    0.0,
                )
                .note("the family's check generator panicked (a bug)");
                (vec![c], f64::NAN)
            });
            checks.extend(c);
            times.push((f.name, t));
        }
        (checks, times)
    })
}

/// Jet derivatives against finite differences for every `Surface` sample of
/// every family (the samples live in each family's `samples.rs`). A sample
/// that fails to build is a failing check.
pub fn derivative_checks() -> Vec<Check> {
    use crate::surface::check::derivative_check;
    use crate::surface::Revolution;
    fn built<S: crate::surface::Surface, E: std::fmt::Display>(
        sample: &str,
        paper: &str,
        s: Result<S, E>,
    ) -> Check {
        match s {
            Ok(s) => derivative_check(sample, paper, &s),
            Err(e) => Check::new(
                "derivatives",
                paper,
                "derivatives",
                &format!("derivatives.{sample}"),
                Kind::Reference,
                f64::NAN,
                0.0,
            )
            .note(format!("sample failed to build: {e}")),
        }
    }
    let mut out = vec![
        derivative_check("surface.revolution", "-", &Revolution { r0: 1.0, r1: 0.3 }),
        derivative_check(
            "mesh.torus",
            "-",
            &crate::surface::samples::Torus {
                big: crate::mesh::samples::TORUS_RADII.0,
                small: crate::mesh::samples::TORUS_RADII.1,
            },
        ),
        built("pde4.two_sided", "000", crate::pde4::samples::two_sided()),
        built("pde4.four_sided", "000", crate::pde4::samples::four_sided()),
        built("ode6.patch", "004", crate::ode6::samples::patch()),
        built(
            "ode6.chain_3_paper_params",
            "004",
            crate::ode6::samples::paper_chain(),
        ),
        built(
            "pde4.deformed_revolution",
            "000",
            crate::pde4::samples::deformed_revolution(),
        ),
        built(
            "ode6.grid_3x2_column",
            "004",
            crate::ode6::samples::grid_3x2().map(|g| g.patches[1][0].clone()),
        ),
    ];
    for (name, a) in crate::pde6::samples::SIGNS {
        out.push(built(
            &format!("pde6.method2_chain_{name}"),
            "002",
            crate::pde6::samples::chain(a),
        ));
    }
    out
}

#[cfg(test)]
mod mutants_oracle;
