//! Extended XYZ (as ASE and OVITO read it): per frame the particle count, a
//! comment line of `key=value` pairs (`Lattice`, `Properties`, `Time`,
//! `pbc`), then a line per particle: species, position, velocity. Positions
//! are the box's own, [0, L) from the origin, as the lattice vectors are;
//! 1D and 2D are padded with zero coordinates and zero lattice vectors
//! (`pbc` F on them). Numbers are written shortest-exact (they read back
//! bit for bit); whitespace in a species name becomes `_`.

use super::{Frame, FrameSink, Layout};
use std::io::{self, Write};

/// An extended XYZ file on `W`, written as frames come.
pub struct Xyz<W: Write> {
    out: W,
    names: Vec<String>,
}

impl<W: Write> Xyz<W> {
    pub fn new(out: W) -> Self {
        Xyz {
            out,
            names: Vec::new(),
        }
    }

    pub fn into_inner(self) -> W {
        self.out
    }
}

/// `T` or `F`.
fn flag(b: bool) -> char {
    if b { 'T' } else { 'F' }
}

impl<W: Write> FrameSink for Xyz<W> {
    fn frame(&mut self, layout: &Layout, frame: &Frame) -> io::Result<()> {
        if self.names.is_empty() {
            self.names = layout
                .species
                .iter()
                .map(|s| s.split_whitespace().collect::<Vec<_>>().join("_"))
                .collect();
        }
        let l = layout.size;
        let p = layout.periodic;
        writeln!(self.out, "{}", frame.positions.len())?;
        writeln!(
            self.out,
            "Lattice=\"{:?} 0 0 0 {:?} 0 0 0 {:?}\" Properties=type:S:1:pos:R:3:vel:R:3 Time={:?} pbc=\"{} {} {}\"",
            l[0],
            l[1],
            l[2],
            frame.time,
            flag(p[0]),
            flag(p[1]),
            flag(p[2])
        )?;
        for (i, (x, v)) in frame.positions.iter().zip(frame.velocities).enumerate() {
            let name = self
                .names
                .get(layout.typeid[i] as usize)
                .map_or("X", String::as_str);
            writeln!(
                self.out,
                "{name} {:?} {:?} {:?} {:?} {:?} {:?}",
                x[0], x[1], x[2], v[0], v[1], v[2]
            )?;
        }
        Ok(())
    }

    fn finish(&mut self, _: &Layout) -> io::Result<()> {
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_is_a_count_a_comment_and_a_line_per_particle() {
        let layout = Layout {
            dimension: 1,
            size: [10.0, 0.0, 0.0],
            periodic: [true, false, false],
            species: vec!["big rod".into()],
            typeid: vec![0, 0],
            diameter: vec![1.0, 1.0],
            mass: vec![1.0, 1.0],
        };
        let mut xyz = Xyz::new(Vec::new());
        let frame = Frame {
            index: 0,
            time: 0.1,
            positions: &[[0.3, 0.0, 0.0], [9.75, 0.0, 0.0]],
            velocities: &[[1e-7, 0.0, 0.0], [-2.0, 0.0, 0.0]],
            images: &[[0; 3]; 2],
        };
        xyz.frame(&layout, &frame).unwrap();
        xyz.finish(&layout).unwrap();
        let text = String::from_utf8(xyz.into_inner()).unwrap();
        assert_eq!(
            text,
            "2\n\
             Lattice=\"10.0 0 0 0 0.0 0 0 0 0.0\" Properties=type:S:1:pos:R:3:vel:R:3 Time=0.1 pbc=\"T F F\"\n\
             big_rod 0.3 0.0 0.0 1e-7 0.0 0.0\n\
             big_rod 9.75 0.0 0.0 -2.0 0.0 0.0\n"
        );
    }
}
