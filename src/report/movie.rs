//! A film as an animated SVG: plays by itself in any browser (and in slides
//! that show SVG), and `html.rs` adds a pause button and a time slider when
//! it sits in `index.html`.
//!
//! Frames change discretely (`calcMode="discrete"`): a frame shows the
//! particles exactly where the engine had them at that time, and nothing is
//! drawn between frames (a linear blend would pass particles through each
//! other and across periodic boundaries).

use crate::model::chart::colour;
use crate::model::movie::Film;
use crate::stats::format::num;
use std::fmt::Write;

/// Widest and tallest picture of the box, in pixels.
const WIDTH: f64 = 720.0;
const MAX_HEIGHT: f64 = 480.0;
/// Height of the 1D track: rods sit on it, velocity arrows above them.
const TRACK: f64 = 90.0;
/// Frames shown per second of playback (the film lasts at least 2 s).
const FPS: f64 = 20.0;

/// Seconds one pass of the film takes to play.
pub fn playback_seconds(film: &Film) -> f64 {
    (film.times.len() as f64 / FPS).max(2.0)
}

/// The whole animated SVG document.
pub fn svg(film: &Film) -> String {
    let (lx, ly) = (film.size[0].max(f64::MIN_POSITIVE), film.size[1]);
    let scale = if film.dimension == 1 || ly <= 0.0 {
        WIDTH / lx
    } else {
        (WIDTH / lx).min(MAX_HEIGHT / ly)
    };
    let width = lx * scale;
    let height = if film.dimension == 1 {
        TRACK
    } else {
        ly * scale
    };
    let duration = film.times.last().copied().unwrap_or(0.0);
    let play = playback_seconds(film);
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"movie\" width=\"{w:.0}\" \
         height=\"{h:.0}\" viewBox=\"-2 -2 {vw:.1} {vh:.1}\" data-duration=\"{duration}\" \
         data-playback=\"{play}\" data-frames=\"{frames}\" role=\"img\">\n\
         <title>run {run}: t = 0 to {shown} in {frames} frames</title>\n\
         <rect x=\"0\" y=\"0\" width=\"{width:.1}\" height=\"{height:.1}\" fill=\"white\" \
         stroke=\"#333\" stroke-width=\"1.5\"/>\n",
        w = width + 4.0,
        h = height + 4.0,
        vw = width + 4.0,
        vh = height + 4.0,
        frames = film.times.len(),
        run = film.run_id,
        shown = num(duration),
    );
    let animate = |name: &str, values: &[f64]| -> String {
        let first = values.first().copied().unwrap_or(0.0);
        if values.iter().all(|v| (v - first).abs() < 0.05) {
            return String::new();
        }
        let list: Vec<String> = values.iter().map(|v| format!("{v:.1}")).collect();
        format!(
            "<animate attributeName=\"{name}\" dur=\"{play}s\" repeatCount=\"indefinite\" \
             calcMode=\"discrete\" values=\"{}\"/>",
            list.join(";")
        )
    };
    let fill = |species: u16| {
        let (r, g, b) = colour(species as usize).rgb;
        format!("rgb({r},{g},{b})")
    };
    if film.dimension == 1 {
        // Arrows: the fastest particle's is a tenth of the picture long.
        let fastest = film
            .tracks
            .iter()
            .flat_map(|t| &t.vx)
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        let arrow = if fastest > 0.0 {
            0.1 * width / fastest
        } else {
            0.0
        };
        let mid = TRACK * 0.65;
        s.push_str(
            "<defs><marker id=\"movie-arrow\" viewBox=\"0 0 6 6\" refX=\"5\" refY=\"3\" \
             markerWidth=\"6\" markerHeight=\"6\" orient=\"auto-start-reverse\">\
             <path d=\"M0,0 L6,3 L0,6 z\" fill=\"#333\"/></marker></defs>\n",
        );
        for t in &film.tracks {
            // Point particles (MacKay's rods have no length) still show.
            let w = (2.0 * t.radius * scale).max(6.0);
            let left: Vec<f64> = t.x.iter().map(|x| x * scale - w / 2.0).collect();
            let centre: Vec<f64> = t.x.iter().map(|x| x * scale).collect();
            let tip: Vec<f64> =
                t.x.iter()
                    .zip(&t.vx)
                    .map(|(x, v)| x * scale + v * arrow)
                    .collect();
            let _ = writeln!(
                s,
                "<rect y=\"{y:.1}\" x=\"{x0:.1}\" width=\"{w:.1}\" height=\"18\" fill=\"{c}\">{a}</rect>",
                y = mid - 9.0,
                x0 = left[0],
                c = fill(t.species),
                a = animate("x", &left),
            );
            let _ = writeln!(
                s,
                "<line y1=\"{y:.1}\" y2=\"{y:.1}\" x1=\"{x1:.1}\" x2=\"{x2:.1}\" stroke=\"#333\" \
                 stroke-width=\"1.5\" marker-end=\"url(#movie-arrow)\">{a1}{a2}</line>",
                y = mid - 18.0,
                x1 = centre[0],
                x2 = tip[0],
                a1 = animate("x1", &centre),
                a2 = animate("x2", &tip),
            );
        }
    } else {
        for t in &film.tracks {
            if t.plane {
                let x: Vec<f64> = t.x.iter().map(|x| x * scale).collect();
                let _ = writeln!(
                    s,
                    "<line y1=\"0\" y2=\"{height:.1}\" x1=\"{x0:.1}\" x2=\"{x0:.1}\" stroke=\"{c}\" \
                     stroke-width=\"{w:.1}\">{a1}{a2}</line>",
                    x0 = x[0],
                    c = fill(t.species),
                    w = (2.0 * t.radius * scale).max(3.0),
                    a1 = animate("x1", &x),
                    a2 = animate("x2", &x),
                );
                continue;
            }
            let x: Vec<f64> = t.x.iter().map(|x| x * scale).collect();
            let y: Vec<f64> = t.y.iter().map(|y| height - y * scale).collect();
            let _ = writeln!(
                s,
                "<circle r=\"{r:.1}\" cx=\"{x0:.1}\" cy=\"{y0:.1}\" fill=\"{c}\" \
                 fill-opacity=\"{o}\">{ax}{ay}</circle>",
                r = (t.radius * scale).max(1.0),
                x0 = x[0],
                y0 = y[0],
                c = fill(t.species),
                o = if film.dimension == 3 { 0.55 } else { 0.9 },
                ax = animate("cx", &x),
                ay = animate("cy", &y),
            );
        }
    }
    s.push_str("</svg>\n");
    s
}

/// The report section's markdown for a film written as `file`.
pub fn section(film: &Film, file: &str) -> String {
    let duration = num(film.times.last().copied().unwrap_or(0.0));
    let species: Vec<String> = film
        .species
        .iter()
        .enumerate()
        .map(|(i, name)| format!("{}: {}", super::markdown::text(name), colour_name(i)))
        .collect();
    let what = match film.dimension {
        1 => "rods on their line, each with an arrow for its velocity",
        2 => "disks in the box",
        _ => "spheres seen along z",
    };
    format!(
        "Run {run} from its start, t = 0 to {duration}, in {frames} \
         frames: {what}. Every frame shows the particles where the engine had them at that \
         time (the run is deterministic, so this is the run as it was measured); nothing is \
         drawn between frames. Colours by species ({species}). The file `{file}` plays on its \
         own in a browser or a slide.\n\n![Run {run}, t = 0 to {duration}]({file})\n",
        run = film.run_id,
        frames = film.times.len(),
        species = species.join(", "),
    )
}

/// The palette's colours by name, in its order.
fn colour_name(i: usize) -> &'static str {
    const NAMES: [&str; 8] = [
        "blue",
        "vermillion",
        "green",
        "orange",
        "pink",
        "sky blue",
        "black",
        "yellow",
    ];
    NAMES[i % NAMES.len()]
}
