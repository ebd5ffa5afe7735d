//! One edit of the bundled female plus the rebuild of the affected part only
//! (`Session::model`, the one `pipeline::build` with the session's part
//! cache: only the edited part's chain is re-solved; the mesh, transitions,
//! props and report are rebuilt), beside two baselines in the same run: the same model path with
//! every part solved (no cache), and the whole document build with its
//! report (`build_document`: profiles read, all parts solved, silhouettes
//! measured). Default resolution (160 rings per height).
//!
//! Each iteration pushes a GEC scale of the left arm with a factor not seen
//! before, so the cache misses on that part and hits on the others.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::character::doc::{CharacterDoc, Level};
use pdesculpt::character::log::{Edit, SectionTransform};
use pdesculpt::character::Resolution;
use pdesculpt::pipeline::build_document;
use pdesculpt::pipeline::Session;
use pdesculpt::sketch::check::bundled;
use std::hint::black_box;
use std::path::{Path, PathBuf};

fn female() -> CharacterDoc {
    let doc = bundled("female", Level::Final).expect("bundled");
    build_document(&doc, Path::new("."), Resolution::default(), true)
        .expect("builds")
        .doc
}

fn edit(i: u64) -> Edit {
    Edit::GecTransform {
        part: "arm_l".into(),
        section: None,
        transform: SectionTransform::Scale {
            sx: 1.0 + 1e-4 * (i % 2000) as f64,
            sy: 1.0,
        },
    }
}

fn bench(c: &mut Criterion) {
    let doc = female();
    let mut warm = Session::new(doc.clone(), PathBuf::from("."), Resolution::default());
    warm.build().expect("builds");
    let mut g = c.benchmark_group("edit");
    let mut i = 0u64;
    g.bench_function("edit_plus_part_rebuild", |b| {
        b.iter(|| {
            i += 1;
            let mut s = warm.clone();
            s.push(edit(i)).expect("valid");
            black_box(s.model().expect("builds"))
        })
    });
    let mut k = 0u64;
    g.bench_function("model_all_parts_solved", |b| {
        b.iter(|| {
            k += 1;
            let mut s = warm.clone();
            s.cache = Default::default();
            s.push(edit(k)).expect("valid");
            black_box(s.model().expect("builds"))
        })
    });
    let mut j = 0u64;
    g.bench_function("whole_rebuild", |b| {
        b.iter(|| {
            j += 1;
            let mut d = doc.clone();
            d.push_edit(edit(j)).expect("valid");
            black_box(
                build_document(&d, Path::new("."), Resolution::default(), false).expect("builds"),
            )
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
