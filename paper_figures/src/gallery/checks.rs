//! Which registered checks each figure relies on: the checks of the
//! equations the figure's code evaluates, listed by hand as check-name
//! prefixes (a prefix ending in `.` takes the whole group), plus every
//! check whose `equation` cites the figure itself ("Fig 8", "Figs 5-6").

use crate::common::Figure;
use pdesculpt::check::Check;

/// Figure id, check-name prefixes.
const RELIES_ON: &[(&str, &[&str])] = &[
    (
        "000-fig1",
        &[
            "pde4.force.",
            "pde4.two_sided.exact_",
            "pde4.two_sided.grid_separable",
        ],
    ),
    (
        "000-fig2",
        &[
            "pde4.four_sided.galerkin_clamped",
            "pde4.four_sided.grid_separable",
            "pde4.force.series_converges_4sided",
            "pde4.force.appendix_",
        ],
    ),
    (
        "000-fig3",
        &[
            "gec.paper_000_literal",
            "gec.derivatives_golden",
            "gec.area_closed_form",
            "gec.refit_",
            "gec.metrics_",
        ],
    ),
    (
        "000-fig8",
        &[
            "pde4.two_sided.boundary_curves",
            "pde4.two_sided.exact_boundary",
            "pde4.two_sided.eq7_basis_clamped",
        ],
    ),
    (
        "000-fig14",
        &[
            "pde4.four_sided.galerkin_clamped",
            "pde4.four_sided.plate_square_point",
            "pde4.force.appendix_concentrated",
        ],
    ),
    (
        "000-pde4-plate",
        &[
            "pde4.four_sided.plate_",
            "pde4.four_sided.fd_reference",
            "pde4.four_sided.eq14_15_vs_plate",
        ],
    ),
    ("000-pde4-twosided", &["pde4.two_sided."]),
    ("001-table-errors", &["plate.reference.", "plate.pipeline."]),
    (
        "001-fig11",
        &["plate.pipeline.", "plate.eq12.", "plate.eq15."],
    ),
    ("001-fig12", &["plate.reference.", "plate.eq12.c1_boundary"]),
    ("001-fig8", &["plate.eq13.", "plate.eq14."]),
    (
        "001-fig9",
        &["plate.eq13.projection", "plate.eq15.", "plate.eq16."],
    ),
    (
        "001-fig1",
        &["plate.rigidity.", "plate.eq12.", "plate.eq16."],
    ),
    (
        "002-table1",
        &[
            "gec.paper_002_literal",
            "gec.refit_",
            "gec.fft_equals_lsq",
            "gec.metrics_",
        ],
    ),
    (
        "002-fig5",
        &[
            "pde6.global_c2_",
            "pde6.global_interpolates_",
            "mesh.torus-cross-section",
        ],
    ),
    (
        "002-fig6",
        &[
            "pde6.global_c2_",
            "pde6.global_interpolates_",
            "mesh.torus-cross-section",
        ],
    ),
    (
        "002-conditioning",
        &[
            "pde6.condition_documented_range",
            "pde6.lebesgue_constants",
            "pde6.method2_amplification",
            "pde6.paper_eq7",
            "pde6.paper_eq8",
        ],
    ),
    (
        "002-fig7a",
        &["pde6.global_", "pde6.closed_v_", "pde6.grid_matches_eval"],
    ),
    ("002-body-ripples", &["pde6.body_"]),
    (
        "003-fig2",
        &[
            "conv.kernel.f1_golden",
            "conv.kernel.ft_golden",
            "conv.weights.",
        ],
    ),
    (
        "003-fig4",
        &["conv.fit.threshold_rms", "conv.weights.exact_threshold"],
    ),
    ("003-fig5", &["conv.fit."]),
    ("003-fig7", &["conv.fit.threshold_rms", "conv.isosurface."]),
    (
        "003-fig8",
        &["conv.silhouette.", "conv.isosurface.star_topology"],
    ),
    (
        "003-polygonizers",
        &["conv.isosurface.", "mesh.torus-topology"],
    ),
    (
        "004-fig2-3",
        &[
            "ode6.boundary.gec_curves",
            "ode6.series_vs_closed_form",
            "ode6.grid_equals_eval",
            "ode6.paper_literal.xi_eq15",
            "ode6.paper_literal.g_eq20",
        ],
    ),
    (
        "004-fig4-5",
        &[
            "ode6.three_point_",
            "ode6.paper_literal.c3_",
            "ode6.paper_literal.c2_",
            "ode6.golden.paper_fig4",
            "ode6.residual.paper_fig4",
            "ode6.boundary.paper_fig4",
        ],
    ),
    (
        "004-fig6",
        &[
            "ode6.continuity_u.",
            "ode6.continuity_v.",
            "ode6.continuity_grid_3x2",
            "ode6.continuity.paper_fig6b",
        ],
    ),
    ("004-fig10", &["ode6.golden.", "ode6.rho_to_zero_limit"]),
    (
        "004-table1",
        &["ode6.continuity_grid_3x2", "ode6.grid_equals_eval"],
    ),
];

/// The figure's number as the checks' `equation` fields cite it
/// ("fig 8", "fig 6b"): digits (and letters) after "fig" in its id.
fn cited_as(id: &str) -> Option<String> {
    let tail = id.split_once("-fig")?.1;
    let n: String = tail.chars().take_while(|c| c.is_ascii_digit()).collect();
    (!n.is_empty()).then_some(n)
}

/// Whether `equation` cites figure number `n` of paper `paper`'s figure.
fn cites(equation: &str, n: &str) -> bool {
    let e = equation.to_ascii_lowercase();
    // "fig 8", "fig 6b", "figs 5-6": every number after a "fig" word
    e.split("fig").skip(1).any(|rest| {
        let rest = rest.trim_start_matches('s').trim_start();
        rest.split(|c: char| !c.is_ascii_alphanumeric())
            .take_while(|t| !t.is_empty())
            .any(|t| t.trim_end_matches(|c: char| c.is_ascii_alphabetic()) == n)
    })
}

/// Entries of the table that no longer match: a figure id not registered,
/// or a prefix that names no registered check (renamed or removed).
pub fn stale(figures: &[Figure], checks: &[Check]) -> Vec<String> {
    let mut out = Vec::new();
    for (id, prefixes) in RELIES_ON {
        if !figures.iter().any(|f| f.id == *id) {
            out.push(format!("figure {id} is not registered"));
        }
        for p in *prefixes {
            if !checks.iter().any(|c| c.name.starts_with(p)) {
                out.push(format!("{id}: no check named {p}*"));
            }
        }
    }
    out
}

/// The checks `f` relies on, in registry order.
pub fn for_figure<'a>(f: &Figure, checks: &'a [Check]) -> Vec<&'a Check> {
    let prefixes = RELIES_ON
        .iter()
        .find(|(id, _)| *id == f.id)
        .map(|(_, p)| *p)
        .unwrap_or(&[]);
    let number = cited_as(f.id);
    checks
        .iter()
        .filter(|c| {
            prefixes.iter().any(|p| c.name.starts_with(p))
                || (c.paper == f.paper && number.as_deref().is_some_and(|n| cites(&c.equation, n)))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equations_citing_a_figure_are_found() {
        assert!(cites("sec 4, Figs 5-6", "5"));
        assert!(cites("sec 4, Figs 5-6", "6"));
        assert!(cites("eq 26, Fig 6b", "6"));
        assert!(cites("sec 5 Fig 8", "8"));
        assert!(!cites("sec 5 Fig 8", "7"));
        assert!(!cites("sec 5 Fig 18", "8"));
        assert!(!cites("eqs 23-26", "2"));
        assert_eq!(cited_as("004-fig2-3").as_deref(), Some("2"));
        assert_eq!(cited_as("003-polygonizers"), None);
    }
}
