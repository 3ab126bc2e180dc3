//! One small chart model and its SVG renderer. Plot builders describe *what*
//! to draw as plain data (`ChartSpec`); only this file talks to plotters, so
//! ranges, log axes, NaN gaps and empty data are handled once.

use crate::stats::format::num;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use std::ops::Range;

pub const WIDTH: u32 = 860;
pub const HEIGHT: u32 = 520;
/// Longest polyline drawn; longer series are thinned so SVGs stay small.
const MAX_POINTS: usize = 1500;
/// Tick and legend text, in plotters' units: it writes a font size of
/// this over 1.24, so 15 is drawn 12.1 px high at the chart's own width,
/// legible on a projector.
const LABEL: u32 = 15;

pub use crate::model::chart::{ChartSpec, Layer, Paint};

/// The plotters style of a paint at a stroke width.
fn style(paint: Paint, width: u32) -> ShapeStyle {
    let (r, g, b) = paint.rgb;
    RGBColor(r, g, b).mix(paint.alpha).stroke_width(width)
}

/// The chart as an SVG document. Never fails: without drawable data (or if
/// plotters gives up) the SVG says so in words instead.
pub fn render(spec: &ChartSpec) -> String {
    let pts = spec.extent_points();
    if pts.is_empty() {
        return placeholder(&spec.title, "no finite data to plot");
    }
    let xr = axis_range(pts.iter().map(|p| p.0), spec.x_log);
    let yr = axis_range(pts.iter().map(|p| p.1), spec.y_log);
    let legend = emptiest_corner(&pts, (&xr, spec.x_log), (&yr, spec.y_log));
    let drawn = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        match (spec.x_log, spec.y_log) {
            (false, false) => draw(spec, legend, xr, yr),
            (true, false) => draw(spec, legend, xr.log_scale(), yr),
            (false, true) => draw(spec, legend, xr, yr.log_scale()),
            (true, true) => draw(spec, legend, xr.log_scale(), yr.log_scale()),
        }
    }));
    match drawn {
        Ok(Ok(svg)) => svg,
        Ok(Err(e)) => placeholder(&spec.title, &format!("plot failed: {e}")),
        Err(_) => placeholder(&spec.title, "plot failed (see stderr)"),
    }
}

/// Data range padded a little; a single value gets a visible span around it.
fn axis_range(values: impl Iterator<Item = f64>, log: bool) -> Range<f64> {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if log {
        let (lo, hi) = if hi > lo {
            (lo, hi)
        } else {
            (lo / 2.0, hi * 2.0)
        };
        let pad = (hi / lo).powf(0.04);
        return lo / pad..hi * pad;
    }
    if hi > lo {
        let pad = 0.05 * (hi - lo);
        lo - pad..hi + pad
    } else {
        let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        lo - pad..hi + pad
    }
}

/// The corner holding the fewest data points, for the legend box.
fn emptiest_corner(
    pts: &[(f64, f64)],
    x: (&Range<f64>, bool),
    y: (&Range<f64>, bool),
) -> SeriesLabelPosition {
    let frac = |v: f64, (r, log): (&Range<f64>, bool)| {
        let (v, lo, hi) = if log {
            (v.ln(), r.start.ln(), r.end.ln())
        } else {
            (v, r.start, r.end)
        };
        (v - lo) / (hi - lo)
    };
    let mut counts = [0usize; 4];
    for &(px, py) in pts {
        let (fx, fy) = (frac(px, x), frac(py, y));
        let right = fx > 0.55;
        let left = fx < 0.45;
        let top = fy > 0.6;
        let bottom = fy < 0.4;
        for (i, hit) in [top && right, top && left, bottom && right, bottom && left]
            .into_iter()
            .enumerate()
        {
            counts[i] += usize::from(hit);
        }
    }
    let corners = [
        SeriesLabelPosition::UpperRight,
        SeriesLabelPosition::UpperLeft,
        SeriesLabelPosition::LowerRight,
        SeriesLabelPosition::LowerLeft,
    ];
    let best = (0..4).min_by_key(|&i| counts[i]).unwrap_or(0);
    corners[best].clone()
}

fn draw<X, Y>(spec: &ChartSpec, legend: SeriesLabelPosition, x: X, y: Y) -> anyhow::Result<String>
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&spec.title, ("sans-serif", 22))
            .margin(14)
            .x_label_area_size(48)
            .y_label_area_size(76)
            .build_cartesian_2d(x, y)
            .map_err(plot_err)?;
        chart
            .configure_mesh()
            .x_desc(spec.x_label.as_str())
            .y_desc(spec.y_label.as_str())
            .axis_desc_style(("sans-serif", 16))
            .label_style(("sans-serif", LABEL))
            .x_labels(10)
            .y_labels(8)
            .max_light_lines(1)
            .light_line_style(RGBColor(240, 240, 240))
            .bold_line_style(RGBColor(215, 215, 215))
            .x_label_formatter(&|v| num(*v))
            .y_label_formatter(&|v| num(*v))
            .draw()
            .map_err(plot_err)?;
        let mut labelled = false;
        for layer in &spec.layers {
            labelled |= draw_layer(&mut chart, spec, layer)?;
        }
        if labelled {
            chart
                .configure_series_labels()
                .position(legend)
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(180, 180, 180))
                .label_font(("sans-serif", LABEL))
                .draw()
                .map_err(plot_err)?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

type Chart<'a, 'b, X, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<X, Y>>;

/// Draw one layer; true if it added a legend entry.
fn draw_layer<'a, 'b: 'a, X, Y>(
    chart: &mut Chart<'a, 'b, X, Y>,
    spec: &ChartSpec,
    layer: &Layer,
) -> anyhow::Result<bool>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let keep = |&(x, y): &(f64, f64)| spec.visible(x, y);
    match layer {
        Layer::Line {
            points,
            paint,
            width,
            dashed,
            label,
        } => {
            let style = style(*paint, *width);
            for (i, piece) in pieces(points, &keep).into_iter().enumerate() {
                let anno = if *dashed {
                    chart.draw_series(DashedLineSeries::new(piece, 8, 5, style))
                } else {
                    chart.draw_series(LineSeries::new(piece, style))
                }
                .map_err(plot_err)?;
                if let (0, Some(label)) = (i, label) {
                    // A dashed legend swatch for dashed lines: two strokes with a gap.
                    let gap = if *dashed { 5 } else { 0 };
                    anno.label(label).legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new(vec![(0, 0), (9, 0)], style)
                            + PathElement::new(vec![(9 + gap, 0), (22, 0)], style)
                    });
                }
            }
            Ok(label.is_some() && points.iter().any(keep))
        }
        Layer::Band {
            x,
            lower,
            upper,
            paint,
        } => {
            let fill = style(*paint, 1).filled();
            let lo: Vec<(f64, f64)> = x.iter().copied().zip(lower.iter().copied()).collect();
            let hi: Vec<(f64, f64)> = x.iter().copied().zip(upper.iter().copied()).collect();
            let both = |i: &usize| keep(&lo[*i]) && keep(&hi[*i]);
            let idx: Vec<usize> = (0..lo.len().min(hi.len())).collect();
            for run in pieces(&idx, &both) {
                let mut poly: Vec<(f64, f64)> = run.iter().map(|&i| lo[i]).collect();
                poly.extend(run.iter().rev().map(|&i| hi[i]));
                chart
                    .draw_series(std::iter::once(Polygon::new(poly, fill)))
                    .map_err(plot_err)?;
            }
            Ok(false)
        }
        Layer::ErrorBars { bars, paint } => {
            let style = style(*paint, 1);
            let ok = bars
                .iter()
                .filter(|(x, lo, c, hi)| keep(&(*x, *lo)) && keep(&(*x, *c)) && keep(&(*x, *hi)));
            chart
                .draw_series(
                    ok.map(|&(x, lo, c, hi)| ErrorBar::new_vertical(x, lo, c, hi, style, 8)),
                )
                .map_err(plot_err)?;
            Ok(false)
        }
        Layer::Markers {
            points,
            paint,
            label,
        } => {
            let style = style(*paint, 1).filled();
            let anno = chart
                .draw_series(
                    points
                        .iter()
                        .filter(|p| keep(p))
                        .map(|&p| Circle::new(p, 4, style)),
                )
                .map_err(plot_err)?;
            if let Some(label) = label {
                anno.label(label)
                    .legend(move |(x, y)| Circle::new((x + 11, y), 4, style));
            }
            Ok(label.is_some() && points.iter().any(keep))
        }
    }
}

/// Maximal runs of items that pass `keep`, each thinned to at most MAX_POINTS.
fn pieces<T: Copy>(items: &[T], keep: &dyn Fn(&T) -> bool) -> Vec<Vec<T>> {
    let mut out: Vec<Vec<T>> = Vec::new();
    let mut current = Vec::new();
    for item in items {
        if keep(item) {
            current.push(*item);
        } else if !current.is_empty() {
            out.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    out.into_iter().map(thin).collect()
}

/// Every k-th item plus the last, so the line keeps its ends.
fn thin<T: Copy>(items: Vec<T>) -> Vec<T> {
    if items.len() <= MAX_POINTS {
        return items;
    }
    let step = items.len().div_ceil(MAX_POINTS);
    let last = items[items.len() - 1];
    let mut out: Vec<T> = items.into_iter().step_by(step).collect();
    out.push(last);
    out
}

fn plot_err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow::anyhow!("{e}")
}

/// A chart-sized SVG that states why there is no plot.
pub fn placeholder(title: &str, message: &str) -> String {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, HEIGHT)).into_drawing_area();
        let centre = |size| {
            ("sans-serif", size).into_font().color(&BLACK).pos(
                plotters::style::text_anchor::Pos::new(
                    plotters::style::text_anchor::HPos::Center,
                    plotters::style::text_anchor::VPos::Center,
                ),
            )
        };
        let mid = (WIDTH as i32 / 2, HEIGHT as i32 / 2);
        // Drawing into a String cannot fail for I/O reasons; if it did, the
        // caller still gets a (shorter) SVG rather than an error.
        let _ = root.fill(&RGBColor(248, 248, 248));
        let _ = root.draw(&Text::new(
            title.to_string(),
            (mid.0, mid.1 - 30),
            centre(22),
        ));
        let _ = root.draw(&Text::new(message.to_string(), mid, centre(16)));
        let _ = root.present();
    }
    svg
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_never_collapse() {
        let r = axis_range([3.0].into_iter(), false);
        assert!(r.start < 3.0 && r.end > 3.0);
        let r = axis_range([0.0, 0.0].into_iter(), false);
        assert!(r.start < 0.0 && r.end > 0.0);
        let r = axis_range([5.0].into_iter(), true);
        assert!(r.start > 0.0 && r.start < 5.0 && r.end > 5.0);
    }

    #[test]
    fn pieces_split_at_nan() {
        let pts = [(0.0, 1.0), (1.0, f64::NAN), (2.0, 2.0), (3.0, 3.0)];
        let p = pieces(&pts, &|&(x, y): &(f64, f64)| x.is_finite() && y.is_finite());
        assert_eq!(p.len(), 2);
        assert_eq!(p[1].len(), 2);
    }
}
