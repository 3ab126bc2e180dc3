//! Chart layers and figures the studies share.

use crate::model::chart::{ChartSpec, Layer, Paint};
use crate::model::report::Figure;
use crate::stats::summary::Stats;

/// A curve of means over replicas against `t`: its band of ± one standard
/// error (nothing is drawn where that is undefined, e.g. one replica) and,
/// on top, its line.
pub fn mean_with_band(t: &[f64], mean: &[Stats], paint: Paint, label: String) -> [Layer; 2] {
    let means = t.iter().zip(mean).map(|(t, s)| (*t, s.mean)).collect();
    [
        Layer::Band {
            x: t.to_vec(),
            lower: mean.iter().map(|s| s.mean - s.stderr).collect(),
            upper: mean.iter().map(|s| s.mean + s.stderr).collect(),
            paint: paint.faded(0.3),
        },
        polyline(means, paint, 2, false, Some(label)),
    ]
}

/// A line `width` pixels wide, dashed or solid (`Layer::Line`'s fields in
/// their order).
pub fn polyline(
    points: Vec<(f64, f64)>,
    paint: Paint,
    width: u32,
    dashed: bool,
    label: Option<String>,
) -> Layer {
    Layer::Line {
        points,
        paint,
        width,
        dashed,
        label,
    }
}

/// Filled circles at `points`.
pub fn markers(points: Vec<(f64, f64)>, paint: Paint, label: Option<String>) -> Layer {
    Layer::Markers {
        points,
        paint,
        label,
    }
}

/// (x, mean − se, mean, mean + se): the error bar of `s` at `x`.
pub fn bar(x: f64, s: &Stats) -> (f64, f64, f64, f64) {
    (x, s.mean - s.stderr, s.mean, s.mean + s.stderr)
}

/// Measured points, each an error bar (x, low, centre, high), and markers
/// at their centres.
pub fn measured(
    bars: impl IntoIterator<Item = (f64, f64, f64, f64)>,
    paint: Paint,
    label: &str,
) -> [Layer; 2] {
    let bars: Vec<_> = bars.into_iter().collect();
    let centres = bars.iter().map(|b| (b.0, b.2)).collect();
    [
        Layer::ErrorBars { bars, paint },
        markers(centres, paint, Some(label.into())),
    ]
}

/// `f` at `n + 1` evenly spaced x from `lo` to `hi`.
pub fn sampled(lo: f64, hi: f64, n: usize, f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    (0..=n)
        .map(|k| lo + (hi - lo) * k as f64 / n as f64)
        .map(|x| (x, f(x)))
        .collect()
}

/// A chart: title and axis labels, which axes (x, y) are logarithmic, and
/// its layers.
pub fn chart(
    (title, x_label, y_label): (impl Into<String>, &str, &str),
    (x_log, y_log): (bool, bool),
    layers: Vec<Layer>,
) -> ChartSpec {
    ChartSpec {
        title: title.into(),
        x_label: x_label.into(),
        y_label: y_label.into(),
        x_log,
        y_log,
        layers,
    }
}

/// A figure in `file`: its chart's `chart` arguments.
pub fn figure(
    file: &str,
    labels: (String, &str, &str),
    logs: (bool, bool),
    layers: Vec<Layer>,
) -> Figure {
    let chart = chart(labels, logs, layers);
    Figure {
        file: file.into(),
        chart,
    }
}

/// The Markdown that shows `figure` under `caption`, the figure added to
/// those the section draws.
pub fn show(figures: &mut Vec<Figure>, figure: Figure, caption: &str) -> String {
    let text = format!("![{caption}]({})\n\n", figure.file);
    figures.push(figure);
    text
}
