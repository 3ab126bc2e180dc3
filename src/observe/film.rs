//! The frames of a movie: at each sample, where every particle is and how
//! fast it moves along x. Not a catalogue observable (it fills no table); the
//! runner films a run with it for `[observe] movie`.

use crate::engine::{Observer, Snapshot};
use crate::model::movie::{Film, Track};

/// Records every sample it is shown into a [`Film`].
pub struct Filming {
    film: Film,
}

impl Filming {
    pub fn new(dimension: usize, size: [f64; 2], species: Vec<String>, run_id: u64) -> Self {
        Filming {
            film: Film {
                dimension,
                size,
                species,
                run_id,
                ..Film::default()
            },
        }
    }

    pub fn into_film(self) -> Film {
        self.film
    }
}

impl<const D: usize> Observer<D> for Filming {
    fn sample(&mut self, s: &Snapshot<D>) {
        let film = &mut self.film;
        if film.tracks.is_empty() {
            film.tracks = s
                .particles
                .iter()
                .map(|p| Track {
                    radius: p.radius,
                    species: p.species,
                    plane: p.is_plane(),
                    ..Track::default()
                })
                .collect();
        }
        film.times.push(s.time);
        for (i, track) in film.tracks.iter_mut().enumerate() {
            let x = s.position(i);
            track.x.push(x[0]);
            track.y.push(if D > 1 { x[1] } else { 0.0 });
            track.vx.push(s.particles[i].vel[0]);
        }
    }
}
