//! Chart layers the studies share.

use crate::model::chart::{Layer, Paint};
use crate::stats::summary::Stats;

/// A curve of means over replicas against `t`: its band of ± one standard
/// error (nothing is drawn where that is undefined, e.g. one replica) and,
/// on top, its line.
pub fn mean_with_band(t: &[f64], mean: &[Stats], paint: Paint, label: String) -> [Layer; 2] {
    [
        Layer::Band {
            x: t.to_vec(),
            lower: mean.iter().map(|s| s.mean - s.stderr).collect(),
            upper: mean.iter().map(|s| s.mean + s.stderr).collect(),
            paint: paint.faded(0.3),
        },
        Layer::Line {
            points: t.iter().zip(mean).map(|(t, s)| (*t, s.mean)).collect(),
            paint,
            width: 2,
            dashed: false,
            label: Some(label),
        },
    ]
}
