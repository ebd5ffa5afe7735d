//! The bundled four-legged animal (body plan quadruped, `sketch::quadruped`).

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use pdesculpt::character::doc::{Level, SectionShape};
use pdesculpt::character::Resolution;
use pdesculpt::pipeline::build_document;
use pdesculpt::sketch::check::{bundled, C1_JUMP};
use std::path::Path;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/sketch");

const PARTS: [&str; 8] = [
    "body", "tail", "back", "head", "leg_br", "leg_bl", "leg_fl", "leg_fr",
];

#[test]
fn every_level_of_the_bundled_animal_is_closed_with_its_parts() {
    for level in [Level::Initial, Level::Intermediate, Level::Final] {
        let doc = bundled("animal", level).expect("bundled animal");
        let b = build_document(&doc, Path::new("."), Resolution::default(), true)
            .unwrap_or_else(|e| panic!("{level:?}: {e}"));
        let t = &b.report.topology;
        assert!(t.watertight && t.manifold && t.oriented, "{level:?}: {t:?}");
        let names: Vec<&str> = b.doc.parts().iter().map(|p| p.name.as_str()).collect();
        let tr = transition_names(&b.doc);
        // the stacked body joined by its transitions, or (below the final
        // level, when it misses the issue's bounds by less) the shells:
        // the back left in the body, no transitions
        if tr.is_empty() {
            assert_ne!(level, Level::Final, "key sections keep the stacked body");
            let shells: Vec<&str> = PARTS.into_iter().filter(|n| *n != "back").collect();
            assert_eq!(names, shells, "{level:?}");
        } else {
            assert_eq!(names, PARTS, "{level:?}");
            assert_eq!(tr, ["underside", "topside"]);
        }
        assert!(
            b.report.max_c1 <= C1_JUMP,
            "{level:?}: C1 {}",
            b.report.max_c1
        );
        // the legs stand on the ground, the far ones (inner) behind the near
        let leg = |n: &str| b.doc.parts().iter().find(|p| p.name == n).expect("leg");
        if level != Level::Initial {
            let z = |n: &str| {
                let sec = &leg(n).sections[3];
                match sec.shape {
                    SectionShape::Ellipse { offset, .. } => sec.centre[2] + offset,
                    _ => sec.centre[2],
                }
            };
            assert!(z("leg_fr") > 0.0 && z("leg_br") > 0.0, "near legs at +z");
            assert!(z("leg_fl") < 0.0 && z("leg_bl") < 0.0, "far legs at -z");
        }
    }
}

#[test]
fn cli_builds_the_animal_and_the_body_plan_overrides() {
    let dir = tmpdir("sketch-animal");
    let out = dir.join("animal.glb");
    let f = format!("{DATA}/animal_front.svg");
    let s = format!("{DATA}/animal_side.svg");
    let o = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        &f,
        "--side",
        &s,
        "-o",
        out.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json report");
    assert_eq!(r["topology"]["watertight"], true);
    assert_eq!(r["level"], "intermediate");
    assert!(out.exists());
    // forcing the humanoid plan on the animal, or the quadruped plan on a
    // humanoid, is a clear error and writes nothing
    let bad = dir.join("bad.obj");
    let o = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        &f,
        "--body-plan",
        "humanoid",
        "-o",
        bad.to_str().unwrap(),
    ]);
    assert_clear_error(&o, "longer than tall");
    let o = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        &format!("{DATA}/female_front.svg"),
        "--body-plan",
        "quadruped",
        "-o",
        bad.to_str().unwrap(),
    ]);
    assert_clear_error(&o, "quadruped");
    let o = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        &f,
        "--body-plan",
        "dog",
        "-o",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "clap rejects an unknown plan");
    assert!(!bad.exists());
}

/// Animals of the corpus drawn with a flat back between a raised tail and a
/// neck (`data/sketch/corpus`: dog and cat, development drawings) build,
/// closed, with the body, tail, head and four legs. Two corners where the
/// tail meets the body (the tail's underside on the rounded rump, and the
/// back line) were read as three parts above the body, the middle one
/// empty ("no outline above the corner"); one corner was found twice on
/// the horse. And the body's depth is the head-on slice's whole extent:
/// at the belly the legs are still apart in the head-on view, and the
/// widest interval (one leg) made the body's lower sections a leg deep
/// (side error 58 % of the height on the cat).
/// How far the body may leave the head-on outline: the issue's 1 % for
/// the stacked body (whose lowest slice stays a join band above the
/// legs' gaps); the shells' body reaches down to the legs' gaps, and the
/// corpus cat's head-on legs merge above its lateral belly (the whole
/// stacked model left its head-on outline by 6.9 % there too). The bug
/// this guards made the body a leg deep: 58 %.
const BODY_SIDE_OUTSIDE: f64 = 0.08;

#[test]
fn corpus_animals_with_a_flat_back_build_with_their_parts() {
    use pdesculpt::pipeline::corpus::read_manifest;
    let m = read_manifest(&Path::new(DATA).join("corpus")).expect("the corpus manifest reads");
    for name in ["dog", "cat"] {
        let e = m.entries.iter().find(|e| e.name == name).expect("entry");
        assert!(!e.held_out, "{name} is a development drawing");
        let b = corpus_animal(name);
        let mut names: Vec<&str> = b.doc.parts().iter().map(|p| p.name.as_str()).collect();
        names.sort_unstable();
        assert_eq!(
            names,
            ["body", "head", "leg_bl", "leg_br", "leg_fl", "leg_fr", "tail"],
            "{name}"
        );
        let side = part_quality(&b, "body").view("side").expect("side");
        assert!(
            side.outside_rel <= BODY_SIDE_OUTSIDE,
            "{name}: the body leaves the head-on outline by {:.2} % of the height",
            100.0 * side.outside_rel
        );
    }
}

/// The corpus dog raises its tail's tip above its head: the head is the
/// larger part above the body, not the higher one (named by height, the
/// tail took the head-on view's depth and the head became circles: 8.6 %
/// of the height outside the head-on outline). And each leg's closed foot
/// keeps its leg's depth centre where the head-on view has no slice of it
/// at the sole: the near hind leg's tip was pulled to z = 0, under the
/// body's middle (6.2 % outside). Head and tail, and the dog's head-on
/// miss, are checked against the stacked body's numbers before the fix.
/// The corpus dog's largest miss outside its head-on outline: 8.6 % of the
/// height with the tail named head, 6.2 % with the near hind foot at
/// z = 0, 3.3 % with both fixed; the rest is the stacked body's flat belly
/// between the legs (not this test's), so the bound sits between.
const DOG_SIDE_OUTSIDE: f64 = 0.04;

#[test]
fn the_dog_faces_its_head_and_its_feet_stay_under_their_legs() {
    let b = corpus_animal("dog");
    let part = |n: &str| b.doc.parts().iter().find(|p| p.name == n).expect(n);
    let mean_x = |n: &str| {
        let s = &part(n).sections;
        s.iter().map(|q| q.centre[0]).sum::<f64>() / s.len() as f64
    };
    // the generator draws the head toward +x
    assert!(mean_x("head") > 0.0 && mean_x("tail") < 0.0);
    assert!(
        matches!(part("head").sections[3].shape, SectionShape::Ellipse { .. }),
        "the head takes its depth from the head-on view"
    );
    for leg in ["leg_fl", "leg_fr", "leg_bl", "leg_br"] {
        let s = &part(leg).sections;
        let z = |q: &pdesculpt::character::doc::SectionSpec| match q.shape {
            SectionShape::Ellipse { offset, .. } => q.centre[2] + offset,
            _ => q.centre[2],
        };
        let (tip, above) = (&s[s.len() - 1], &s[s.len() - 2]);
        let r = match above.shape {
            SectionShape::Ellipse { a, b, .. } => a.max(b),
            SectionShape::Circle { r } => r,
            _ => 0.0,
        };
        assert!(
            (z(tip) - z(above)).abs() <= r,
            "{leg}: tip at z = {:.4}, the section above at {:.4} (radius {r:.4})",
            z(tip),
            z(above)
        );
    }
    let side = b.report.quality.whole.view("side").expect("side");
    assert!(
        side.outside_rel < DOG_SIDE_OUTSIDE,
        "the dog leaves its head-on outline by {:.2} % of the height",
        100.0 * side.outside_rel
    );
}

/// An animal with one part above its back (the corpus dog with its tail
/// hanging down: no corner between two rising parts) was refused ("found
/// 0 corner(s)"); the back line under its lone neck is now found where
/// the slices step from the neck's width to the body's
/// (`quadruped::landmarks::back_line`), and it builds closed with its
/// head toward +x. Its hanging tail is a part of its own
/// (`quadruped::hanging`): left out before, the front missed it by 20 %
/// of the height.
#[test]
fn a_dog_with_its_tail_down_builds_with_its_head_over_the_back() {
    let b = corpus_animal("dog_tail_down_two_legs");
    let mut names: Vec<&str> = b.doc.parts().iter().map(|p| p.name.as_str()).collect();
    names.sort_unstable();
    assert_eq!(
        names,
        ["body", "head", "leg_bl", "leg_br", "leg_fl", "leg_fr", "tail"]
    );
    let head = b
        .doc
        .parts()
        .iter()
        .find(|p| p.name == "head")
        .expect("head");
    assert!(
        head.sections.iter().all(|s| s.centre[0] > 0.0),
        "the head faces +x"
    );
    hanging_part_follows_its_outline(&b, "tail");
}

/// A lateral view with two legs (each hiding its pair's far leg) whose
/// head-on view shows the left and right legs apart is built with the
/// four legs (`quadruped::shells::leg_pair`): each takes its depth from
/// its own side of the head-on view, the near one (`_r` facing +x) at
/// +z. Built as two legs spanning the head-on view first to last, the
/// legs filled the gap between them: the corpus dog with its tail down
/// left its head-on outline by 7.2 % of the height, the elephant by
/// 8.5 %; each leg of the pairs now stays within issue 28's outside
/// bound (0.2 %).
#[test]
fn a_two_legged_lateral_view_builds_the_pairs_the_head_on_view_shows_apart() {
    use pdesculpt::sketch::quality::Bounds;
    for name in ["dog_tail_down_two_legs", "elephant"] {
        let b = corpus_animal(name);
        let mean_z = |n: &str| {
            let p = b.doc.parts().iter().find(|p| p.name == n).expect(n);
            // an ellipse's depth centre is offset along e2 = z
            let z = |q: &pdesculpt::character::doc::SectionSpec| match q.shape {
                SectionShape::Ellipse { offset, .. } => q.centre[2] + offset * q.e2[2],
                _ => q.centre[2],
            };
            p.sections.iter().map(z).sum::<f64>() / p.sections.len() as f64
        };
        for pair in ["leg_f", "leg_b"] {
            // both drawings face +x: the right leg is the near one
            let (l, r) = (mean_z(&format!("{pair}l")), mean_z(&format!("{pair}r")));
            assert!(l < r, "{name} {pair}: left at z = {l:.4}, right at {r:.4}");
            for leg in [format!("{pair}l"), format!("{pair}r")] {
                let side = part_quality(&b, &leg).view("side").expect("side");
                assert!(
                    side.outside_rel <= Bounds::ISSUE.outside,
                    "{name} {leg}: {:.2} % of the height outside the head-on outline",
                    100.0 * side.outside_rel
                );
            }
        }
    }
}

/// A hanging part's own front miss and how far it leaves the drawn
/// outline are within issue 28's bounds, and the tail hangs behind the
/// legs (-x, the head at +x) or the trunk in front of them.
fn hanging_part_follows_its_outline(b: &pdesculpt::pipeline::Built, name: &str) {
    use pdesculpt::sketch::quality::Bounds;
    let front = part_quality(b, name).view("front").expect("front");
    assert!(
        front.max_rel <= Bounds::ISSUE.profile_front && front.outside_rel <= Bounds::ISSUE.outside,
        "{name}: front miss {:.2} %, outside {:.2} % of the height",
        100.0 * front.max_rel,
        100.0 * front.outside_rel
    );
    let part = b.doc.parts().iter().find(|p| p.name == name).expect(name);
    let x = part.sections.iter().map(|s| s.centre[0]).sum::<f64>() / part.sections.len() as f64;
    let legs: Vec<f64> = b
        .doc
        .parts()
        .iter()
        .filter(|p| p.name.starts_with("leg"))
        .flat_map(|p| p.sections.iter().map(|s| s.centre[0]))
        .collect();
    let (lo, hi) = legs
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    assert!(
        if name == "tail" { x < lo } else { x > hi },
        "{name} at x = {x:.4}, the legs between {lo:.4} and {hi:.4}"
    );
}

/// The corpus elephant: its head level with the back, in front of the
/// body, nothing rising above the back. It was refused ("found 0
/// corner(s)"); the body's slices now reach the top and close there, with
/// no `topside`. Its trunk hangs from the head, a part of its own
/// (`quadruped::hanging`): left out before, the front missed it by 46 %
/// of the height.
#[test]
fn an_elephant_with_nothing_above_its_back_builds_closed() {
    let b = corpus_animal("elephant");
    let names: Vec<&str> = b.doc.parts().iter().map(|p| p.name.as_str()).collect();
    assert_eq!(
        names,
        ["body", "leg_bl", "leg_br", "leg_fl", "leg_fr", "trunk"]
    );
    assert!(b.doc.parts()[0].closed_end, "the body closes at the top");
    // it faces +x (the generator's head): the front leg is the one at +x
    let mean_x = |n: &str| {
        let s = &b
            .doc
            .parts()
            .iter()
            .find(|p| p.name == n)
            .expect(n)
            .sections;
        s.iter().map(|q| q.centre[0]).sum::<f64>() / s.len() as f64
    };
    assert!(mean_x("leg_fr") > mean_x("leg_br"));
    // the stacked body's underside, or the shells (no transitions)
    let tr = transition_names(&b.doc);
    assert!(tr.is_empty() || tr == ["underside"], "{tr:?}");
    hanging_part_follows_its_outline(&b, "trunk");
}

/// A corpus animal built as a user would (intermediate level), checked
/// closed.
fn corpus_animal(name: &str) -> pdesculpt::pipeline::Built {
    use pdesculpt::pipeline::corpus::{build_entry, read_manifest};
    let dir = Path::new(DATA).join("corpus");
    let m = read_manifest(&dir).expect("the corpus manifest reads");
    let e = m.entries.iter().find(|e| e.name == name).expect(name);
    let b = build_entry(&dir, e).unwrap_or_else(|err| panic!("{name}: {err}"));
    let t = &b.report.topology;
    assert!(t.watertight && t.manifold && t.oriented, "{name}: {t:?}");
    b
}

/// The names of a document's transitions, in order.
fn transition_names(doc: &pdesculpt::character::doc::CharacterDoc) -> Vec<&str> {
    doc.transitions().iter().map(|t| t.name.as_str()).collect()
}

/// A part's quality row in a build's report.
fn part_quality<'a>(
    b: &'a pdesculpt::pipeline::Built,
    name: &str,
) -> &'a pdesculpt::sketch::quality::PartQuality {
    b.report
        .quality
        .parts
        .iter()
        .find(|p| p.part == name)
        .unwrap_or_else(|| panic!("{name} is measured"))
}
