//! A chart as plain data: what to draw, not how. Studies and the generic
//! plots describe charts with these types; `report::chart` renders them.

/// What to draw in one chart.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ChartSpec {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub x_log: bool,
    pub y_log: bool,
    pub layers: Vec<Layer>,
}

/// A colour with opacity (light traces and bands are translucent).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Paint {
    pub rgb: (u8, u8, u8),
    pub alpha: f64,
}

impl Paint {
    pub fn solid(rgb: (u8, u8, u8)) -> Paint {
        Paint { rgb, alpha: 1.0 }
    }
    pub fn faded(self, alpha: f64) -> Paint {
        Paint { alpha, ..self }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum Layer {
    /// A polyline; non-finite points break it into pieces.
    Line {
        points: Vec<(f64, f64)>,
        paint: Paint,
        width: u32,
        dashed: bool,
        label: Option<String>,
    },
    /// Filled region between `lower` and `upper` sampled at the same `x`.
    Band {
        x: Vec<f64>,
        lower: Vec<f64>,
        upper: Vec<f64>,
        paint: Paint,
    },
    /// Vertical error bars: (x, low, centre, high).
    ErrorBars {
        bars: Vec<(f64, f64, f64, f64)>,
        paint: Paint,
    },
    /// Filled circles.
    Markers {
        points: Vec<(f64, f64)>,
        paint: Paint,
        label: Option<String>,
    },
}

impl ChartSpec {
    /// All finite points the axes must show (on log axes only positive ones).
    pub fn extent_points(&self) -> Vec<(f64, f64)> {
        let mut pts = Vec::new();
        for layer in &self.layers {
            match layer {
                Layer::Line { points, .. } | Layer::Markers { points, .. } => {
                    pts.extend(points.iter().copied())
                }
                Layer::Band {
                    x, lower, upper, ..
                } => {
                    for ((x, lo), hi) in x.iter().zip(lower).zip(upper) {
                        pts.push((*x, *lo));
                        pts.push((*x, *hi));
                    }
                }
                Layer::ErrorBars { bars, .. } => {
                    for (x, lo, c, hi) in bars {
                        pts.extend([(*x, *lo), (*x, *c), (*x, *hi)]);
                    }
                }
            }
        }
        pts.retain(|&(x, y)| self.visible(x, y));
        pts
    }

    pub fn visible(&self, x: f64, y: f64) -> bool {
        x.is_finite() && y.is_finite() && (!self.x_log || x > 0.0) && (!self.y_log || y > 0.0)
    }
}

/// Okabe and Ito's palette: told apart with the common colour-vision
/// deficiencies, readable on white (its yellow last: faint on white).
const PALETTE: [(u8, u8, u8); 8] = [
    (0, 114, 178),
    (213, 94, 0),
    (0, 158, 115),
    (230, 159, 0),
    (204, 121, 167),
    (86, 180, 233),
    (0, 0, 0),
    (240, 228, 66),
];

/// The `i`th colour of the palette, cycling.
pub fn colour(i: usize) -> Paint {
    Paint::solid(PALETTE[i % PALETTE.len()])
}
