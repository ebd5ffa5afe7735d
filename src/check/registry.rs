//! Gathers every family's checks.

use super::Check;

/// One equation family and its check generator.
pub struct Family {
    pub name: &'static str,
    /// Papers it implements (file numbers).
    pub papers: &'static str,
    pub checks: fn() -> Vec<Check>,
}

/// Every family, in dependency order.
pub fn families() -> &'static [Family] {
    &[
        Family {
            name: "jet",
            papers: "-",
            checks: crate::jet::check::checks,
        },
        Family {
            name: "mesh",
            papers: "-",
            checks: crate::mesh::check::checks,
        },
        Family {
            name: "surface",
            papers: "-",
            checks: crate::surface::check::checks,
        },
        Family {
            name: "gec",
            papers: "000, 002",
            checks: crate::curve::gec::check::checks,
        },
        Family {
            name: "pde4",
            papers: "000",
            checks: crate::pde4::check::checks,
        },
        Family {
            name: "plate",
            papers: "001",
            checks: crate::plate::check::checks,
        },
        Family {
            name: "pde6",
            papers: "002",
            checks: crate::pde6::check::checks,
        },
        Family {
            name: "ode6",
            papers: "004",
            checks: crate::ode6::check::checks,
        },
        Family {
            name: "conv",
            papers: "003",
            checks: crate::conv::check::checks,
        },
        Family {
            name: "profile",
            papers: "000",
            checks: crate::profile::check::checks,
        },
        Family {
            name: "template",
            papers: "000",
            checks: crate::template::check::checks,
        },
    ]
}

/// Runs the checks of every family whose name equals `family` (all when
/// `None`). Families run in parallel threads; the order of the result is the
/// registry order.
pub fn run(family: Option<&str>) -> Vec<Check> {
    let selected: Vec<&Family> = families()
        .iter()
        .filter(|f| family.is_none_or(|n| n == f.name))
        .collect();
    std::thread::scope(|s| {
        let handles: Vec<_> = selected
            .iter()
            .map(|f| s.spawn(move || (f.checks)()))
            .collect();
        handles
            .into_iter()
            .zip(&selected)
            .flat_map(|(h, f)| {
                h.join().unwrap_or_else(|_| {
                    vec![Check::new(
                        f.name,
                        f.papers,
                        "-",
                        &format!("{}.checks-panicked", f.name),
                        super::Kind::Reference,
                        f64::NAN,
                        0.0,
                    )
                    .note("the family's check generator panicked (a bug)")]
                })
            })
            .collect()
    })
}
