//! HOOMD's GSD schema (`hoomd` 2.0, doubles) in GSD's file layer 2.0, written
//! by hand: a 256-byte header, the data chunks frame after frame, then the
//! index (32 bytes an entry, sorted by frame and then name id) and the list
//! of names (0-terminated, in a block of 64-byte units), whose places the
//! header, written again last, gives. Frame 0 holds every chunk; later
//! frames only what moves (step, position, velocity, image, `log/time`):
//! the schema reads a chunk missing from a frame from frame 0.
//!
//! Positions are the box's [0, L) shifted to HOOMD's [-L/2, L/2) on every
//! axis of the scene. 2D is `dimensions = 2` with Lz = 0 (z = 0), as HOOMD
//! and `gsd.hoomd` read a 2D box; 1D is stored as 2D with Ly = 1 (y = 0).

use super::{FrameSink, Layout};
use std::io::{self, Seek, SeekFrom, Write};

const MAGIC: u64 = 0x65DF_65DF_65DF_65DF;
/// `major << 16 | minor`.
const FILE_VERSION: u32 = 2 << 16;
const SCHEMA_VERSION: u32 = 2 << 16;
const HEADER: u64 = 256;
const NAME_UNIT: usize = 64;

/// GSD's type codes.
const UINT8: u8 = 1;
const UINT32: u8 = 3;
const UINT64: u8 = 4;
const INT8: u8 = 5;
const INT32: u8 = 7;
const DOUBLE: u8 = 10;

/// Chunk names in the order of their ids; each frame writes its chunks in
/// this order, so the index is sorted by id within a frame.
const NAMES: [&str; 12] = [
    "configuration/step",
    "configuration/dimensions",
    "configuration/box",
    "particles/N",
    "particles/types",
    "particles/typeid",
    "particles/mass",
    "particles/diameter",
    "particles/position",
    "particles/velocity",
    "particles/image",
    "log/time",
];

fn id(name: &str) -> u16 {
    NAMES
        .iter()
        .position(|n| *n == name)
        .expect("a known chunk") as u16
}

/// One index entry.
struct Entry {
    frame: u64,
    n: u64,
    location: u64,
    m: u32,
    id: u16,
    kind: u8,
}

/// A GSD file on `W`, written as frames come.
pub struct Gsd<W: Write + Seek> {
    out: W,
    at: u64,
    index: Vec<Entry>,
}

impl<W: Write + Seek> Gsd<W> {
    /// Start the file: the header's room (filled in by `finish`).
    pub fn new(mut out: W) -> io::Result<Self> {
        out.write_all(&[0; HEADER as usize])?;
        Ok(Gsd {
            out,
            at: HEADER,
            index: Vec::new(),
        })
    }

    pub fn into_inner(self) -> W {
        self.out
    }

    fn chunk(
        &mut self,
        frame: u64,
        name: &str,
        kind: u8,
        n: u64,
        m: u32,
        bytes: &[u8],
    ) -> io::Result<()> {
        self.index.push(Entry {
            frame,
            n,
            location: self.at,
            m,
            id: id(name),
            kind,
        });
        self.out.write_all(bytes)?;
        self.at += bytes.len() as u64;
        Ok(())
    }

    fn doubles(
        &mut self,
        frame: u64,
        name: &str,
        rows: u64,
        m: u32,
        values: impl Iterator<Item = f64>,
    ) -> io::Result<()> {
        let bytes: Vec<u8> = values.flat_map(f64::to_le_bytes).collect();
        self.chunk(frame, name, DOUBLE, rows, m, &bytes)
    }
}

/// The box and the HOOMD dimension of a layout: [Lx, Ly, Lz, 0, 0, 0].
fn hoomd_box(layout: &Layout) -> ([f64; 6], u8) {
    let l = layout.size;
    match layout.dimension {
        1 => ([l[0], 1.0, 0.0, 0.0, 0.0, 0.0], 2),
        2 => ([l[0], l[1], 0.0, 0.0, 0.0, 0.0], 2),
        _ => ([l[0], l[1], l[2], 0.0, 0.0, 0.0], 3),
    }
}

impl<W: Write + Seek> FrameSink for Gsd<W> {
    fn frame(&mut self, layout: &Layout, frame: &super::Frame) -> io::Result<()> {
        let f = frame.index;
        let n = frame.positions.len() as u64;
        let d = layout.dimension;
        self.chunk(f, "configuration/step", UINT64, 1, 1, &f.to_le_bytes())?;
        if f == 0 {
            let (b, dimensions) = hoomd_box(layout);
            self.chunk(f, "configuration/dimensions", UINT8, 1, 1, &[dimensions])?;
            self.doubles(f, "configuration/box", 6, 1, b.into_iter())?;
            self.chunk(f, "particles/N", UINT32, 1, 1, &(n as u32).to_le_bytes())?;
            let width = layout.species.iter().map(String::len).max().unwrap_or(0) + 1;
            let mut types = vec![0u8; width * layout.species.len()];
            for (row, name) in layout.species.iter().enumerate() {
                types[row * width..row * width + name.len()].copy_from_slice(name.as_bytes());
            }
            let (rows, width) = (layout.species.len() as u64, width as u32);
            self.chunk(f, "particles/types", INT8, rows, width, &types)?;
            let ids: Vec<u8> = layout.typeid.iter().flat_map(|t| t.to_le_bytes()).collect();
            self.chunk(f, "particles/typeid", UINT32, n, 1, &ids)?;
            self.doubles(f, "particles/mass", n, 1, layout.mass.iter().copied())?;
            self.doubles(
                f,
                "particles/diameter",
                n,
                1,
                layout.diameter.iter().copied(),
            )?;
        }
        let shift = |x: &[f64; 3]| -> [f64; 3] {
            std::array::from_fn(|k| {
                if k < d {
                    x[k] - 0.5 * layout.size[k]
                } else {
                    x[k]
                }
            })
        };
        let positions = frame.positions.iter().flat_map(shift);
        self.doubles(f, "particles/position", n, 3, positions)?;
        let velocities = frame.velocities.iter().flatten().copied();
        self.doubles(f, "particles/velocity", n, 3, velocities)?;
        if layout.periodic.iter().any(|&p| p) {
            let images: Vec<u8> = frame
                .images
                .iter()
                .flatten()
                .flat_map(|i| i.to_le_bytes())
                .collect();
            self.chunk(f, "particles/image", INT32, n, 3, &images)?;
        }
        self.doubles(f, "log/time", 1, 1, std::iter::once(frame.time))
    }

    fn finish(&mut self, _: &Layout) -> io::Result<()> {
        // The index, with one empty entry (location 0) that ends it.
        let index_at = self.at;
        let mut bytes = Vec::with_capacity(32 * (self.index.len() + 1));
        for e in &self.index {
            bytes.extend(e.frame.to_le_bytes());
            bytes.extend(e.n.to_le_bytes());
            bytes.extend(e.location.to_le_bytes());
            bytes.extend(e.m.to_le_bytes());
            bytes.extend(e.id.to_le_bytes());
            bytes.push(e.kind);
            bytes.push(0); // flags
        }
        bytes.extend([0; 32]);
        let entries = self.index.len() as u64 + 1;
        // The names, and at least one 0 after the last: an empty name ends them.
        let mut names: Vec<u8> = NAMES.iter().flat_map(|n| n.bytes().chain([0])).collect();
        names.resize((names.len() / NAME_UNIT + 1) * NAME_UNIT, 0);
        let names_at = index_at + bytes.len() as u64;
        self.out.write_all(&bytes)?;
        self.out.write_all(&names)?;
        let mut header = Vec::with_capacity(HEADER as usize);
        header.extend(MAGIC.to_le_bytes());
        header.extend(index_at.to_le_bytes());
        header.extend(entries.to_le_bytes());
        header.extend(names_at.to_le_bytes());
        header.extend(((names.len() / NAME_UNIT) as u64).to_le_bytes());
        header.extend(SCHEMA_VERSION.to_le_bytes());
        header.extend(FILE_VERSION.to_le_bytes());
        header.extend(name_field("bonkers"));
        header.extend(name_field("hoomd"));
        header.resize(HEADER as usize, 0);
        self.out.seek(SeekFrom::Start(0))?;
        self.out.write_all(&header)?;
        self.out.flush()
    }
}

/// A 64-byte, 0-padded name of the header.
fn name_field(name: &str) -> [u8; NAME_UNIT] {
    let mut field = [0; NAME_UNIT];
    field[..name.len()].copy_from_slice(name.as_bytes());
    field
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::observe::trajectory::Frame;
    use std::io::Cursor;

    fn u64_at(b: &[u8], at: usize) -> u64 {
        u64::from_le_bytes(b[at..at + 8].try_into().unwrap())
    }

    /// Our own file read back by the layout of GSD's file layer: header,
    /// index sorted by (frame, id), names, and each chunk's bytes.
    #[test]
    fn the_file_layer_reads_back() {
        let layout = Layout {
            dimension: 2,
            size: [4.0, 6.0, 0.0],
            periodic: [true, false, false],
            species: vec!["a".into(), "bee".into()],
            typeid: vec![0, 1],
            diameter: vec![1.0, 0.5],
            mass: vec![1.0, f64::INFINITY],
        };
        let mut gsd = Gsd::new(Cursor::new(Vec::new())).unwrap();
        let positions = [[1.0, 2.0, 0.0], [3.5, 0.25, 0.0]];
        let velocities = [[0.5, -1.0, 0.0], [0.0, 0.0, 0.0]];
        for index in 0..2 {
            let images = [[index as i32, 0, 0], [0, 0, 0]];
            let frame = Frame {
                index,
                time: 0.5 * index as f64,
                positions: &positions,
                velocities: &velocities,
                images: &images,
            };
            gsd.frame(&layout, &frame).unwrap();
        }
        gsd.finish(&layout).unwrap();
        let b = gsd.into_inner().into_inner();
        assert_eq!(u64_at(&b, 0), MAGIC);
        let (index_at, entries) = (u64_at(&b, 8) as usize, u64_at(&b, 16) as usize);
        let (names_at, name_units) = (u64_at(&b, 24) as usize, u64_at(&b, 32) as usize);
        assert_eq!(&b[40..48], &[0, 0, 2, 0, 0, 0, 2, 0]); // schema 2.0, file 2.0
        assert_eq!(&b[48..56], b"bonkers\0");
        assert_eq!(&b[112..118], b"hoomd\0");
        assert_eq!(names_at + NAME_UNIT * name_units, b.len());
        let names: Vec<&str> = std::str::from_utf8(&b[names_at..])
            .unwrap()
            .split('\0')
            .take_while(|n| !n.is_empty())
            .collect();
        assert_eq!(names, NAMES);
        // 12 chunks in frame 0, 5 in frame 1, then the empty entry.
        assert_eq!(entries, 18);
        let entry = |i: usize| {
            let e = &b[index_at + 32 * i..index_at + 32 * (i + 1)];
            (
                u64_at(e, 0),
                u64_at(e, 8),
                u64_at(e, 16) as usize,
                e[28],
                e[30],
            )
        };
        let mut last = (0, 0);
        for i in 0..entries - 1 {
            let (frame, _, location, id, _) = entry(i);
            assert!((frame, id) > last || i == 0, "sorted by frame, then id");
            assert!(location >= HEADER as usize && location < index_at);
            last = (frame, id);
        }
        assert_eq!(entry(entries - 1).2, 0, "the index ends with location 0");
        let chunk = |frame: u64, name: &str| {
            let i = (0..entries - 1)
                .find(|&i| entry(i).0 == frame && entry(i).3 == id(name) as u8)
                .unwrap();
            let (_, n, location, _, kind) = entry(i);
            (n, kind, &b[location..])
        };
        let doubles = |bytes: &[u8], n: usize| -> Vec<f64> {
            (0..n)
                .map(|i| f64::from_le_bytes(bytes[8 * i..8 * i + 8].try_into().unwrap()))
                .collect()
        };
        let (_, kind, bytes) = chunk(0, "configuration/box");
        assert_eq!(kind, DOUBLE);
        assert_eq!(doubles(bytes, 6), [4.0, 6.0, 0.0, 0.0, 0.0, 0.0]);
        assert_eq!(chunk(0, "configuration/dimensions").2[0], 2);
        let (n, _, bytes) = chunk(0, "particles/types");
        assert_eq!((n, &bytes[..8]), (2, &b"a\0\0\0bee\0"[..]));
        let (_, _, bytes) = chunk(1, "particles/position");
        assert_eq!(doubles(bytes, 6), [-1.0, -1.0, 0.0, 1.5, -2.75, 0.0]);
        let (_, kind, bytes) = chunk(1, "particles/image");
        assert_eq!((kind, &bytes[..4]), (INT32, &1i32.to_le_bytes()[..]));
        assert_eq!(doubles(chunk(1, "log/time").2, 1), [0.5]);
        assert_eq!(
            doubles(chunk(0, "particles/mass").2, 2),
            [1.0, f64::INFINITY]
        );
    }
}
