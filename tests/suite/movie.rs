//! `[observe] movie`: the film is the run as the engine moved it (the same
//! positions, bit for bit, as the run's own `positions` series at the same
//! times), and it reaches the report as an animated SVG.

use bonkers::descriptor::load::parse;
use bonkers::model::movie::MovieSpec;
use bonkers::report::movie::svg;
use bonkers::runner::execute::movie::film;
use bonkers::runner::execute::simulate;
use bonkers::runner::plan::plan;

const RODS: &str = r#"
[study]
name = "film"
replicas = 1
seed = 5

[scene]
preset = "mackay-piston"
velocities = { kind = "maxwell", temperature = 1.0 }
piston = { mass = 30.0, position = 0.5, radius = 0.0 }

[run]
duration = 12.0
sample_every = 0.25
full_series = true

[observe]
series = ["positions"]
movie = { duration = 12.0, frames = 49 }
"#;

#[test]
fn the_film_is_the_run_bit_for_bit() {
    let loaded = parse("film.toml", RODS).unwrap();
    let spec = plan(&loaded).unwrap().remove(0);
    let movie: MovieSpec = loaded.descriptor.observe.movie.unwrap();
    let film = film(&spec, &movie, u64::MAX).unwrap();
    assert_eq!(film.times.len(), 49);
    assert_eq!(film.times[0], 0.0);
    assert!((film.times[48] - 12.0).abs() < 1e-12);

    // The same run, measured: its positions series samples the same times.
    let out = simulate::run(&spec).unwrap();
    let particles = film.tracks.len();
    assert_eq!(particles, 11, "MacKay's ten rods and the piston");
    for (i, track) in film.tracks.iter().enumerate() {
        let series = out
            .series
            .iter()
            .find(|s| s.observable == format!("x.{i}"))
            .unwrap();
        assert_eq!(series.t, film.times, "sample times of particle {i}");
        assert_eq!(series.value, track.x, "positions of particle {i}");
    }
    // Something happened on screen: the rods moved and collided.
    let moved = film.tracks.iter().filter(|t| t.x[0] != t.x[48]).count();
    assert!(moved >= 10, "{moved} of 11 moved");
    assert!(film.tracks.iter().any(|t| t.vx[0] != t.vx[48]));
}

#[test]
fn the_film_is_an_animated_svg_with_a_frame_per_value() {
    let loaded = parse("film.toml", RODS).unwrap();
    let spec = plan(&loaded).unwrap().remove(0);
    let film = film(
        &spec,
        &MovieSpec {
            duration: 3.0,
            frames: 7,
            run: 0,
        },
        u64::MAX,
    )
    .unwrap();
    let text = svg(&film);
    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    assert!(text.contains("class=\"movie\"") && text.contains("data-duration=\"3\""));
    // Each moving rod: one discrete animation of its x with 7 values.
    let animations: Vec<&str> = text
        .split("<animate attributeName=\"x\" ")
        .skip(1)
        .collect();
    assert!(animations.len() >= 10, "{} rods animated", animations.len());
    for a in animations {
        assert!(a.contains("calcMode=\"discrete\""));
        let values = a
            .split("values=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap();
        assert_eq!(values.split(';').count(), 7);
    }
}
