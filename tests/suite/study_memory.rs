//! What the studies' sections and the report are made from, held without
//! the samples of every run (`stats::ensemble::Runs`): each point's series
//! means over all its replicas, accumulated as the runs stream past, and the
//! series themselves only for the first few replicas.

use crate::study_common::ensemble;
use bonkers::model::run_output::{RunOutput, Series};
use bonkers::stats::ensemble::{KEPT, Runs};
use bonkers::stats::summary::Stats;

const TEXT: &str = r#"
[study]
name = "memory-test"
replicas = 5
seed = 21

[scene]
dimension = 2
box = [20.0, 20.0]
velocities = { kind = "maxwell", temperature = 1.0 }

[[scene.species]]
name = "gas"
count = 30
radius = 0.3
region = { from = [0.0, 0.0], to = [0.5, 1.0] }

[sweep.parameters]
"scene.species.0.count" = [20, 40]

[run]
duration = 30.0
sample_every = 0.5

[analysis.expansion]
"#;

#[test]
fn point_means_cover_every_replica_and_only_the_first_keep_their_series() {
    let all = ensemble(TEXT);
    let runs = Runs::from(all.clone());
    let mut checked = 0;
    for point in [0, 1] {
        let outs: Vec<&RunOutput> = all
            .iter()
            .filter(|(s, _)| s.point_id == point)
            .map(|(_, o)| o)
            .collect();
        assert_eq!(outs.len(), 5);
        for name in outs[0].series.iter().map(|s| s.observable.as_str()) {
            let series: Vec<&Series> = outs.iter().filter_map(|o| o.series(name)).collect();
            let (t, stats) = runs.mean(point, name).expect("a mean curve");
            let len = series.iter().map(|s| s.value.len()).min().unwrap();
            assert_eq!(t, series[0].t[..len]);
            for (i, s) in stats.iter().enumerate() {
                let column: Vec<f64> = series
                    .iter()
                    .map(|x| x.value[i])
                    .filter(|v| v.is_finite())
                    .collect();
                let direct = Stats::of(&column);
                // The same sum in the same order: the mean is bit-identical.
                assert_eq!((s.n, s.mean.to_bits()), (direct.n, direct.mean.to_bits()));
                let scale = direct.std.abs().max(1e-300);
                assert!(
                    (s.std - direct.std).abs() <= 1e-12 * scale.max(direct.mean.abs()),
                    "{name} at {i}: {s:?} against {direct:?}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked} samples checked");
    assert!(runs.mean(7, "left_fraction").is_none());
    for ((spec, out), (_, original)) in runs.iter().zip(&all) {
        assert_eq!(out.scalars, original.scalars);
        assert_eq!(out.series.is_empty(), spec.replica >= KEPT, "{spec:?}");
        if spec.replica < KEPT {
            assert_eq!(out.series, original.series);
        }
    }
}
