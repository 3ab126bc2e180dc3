//! What a particle has scheduled, and how it is kept: 8 bytes a particle
//! instead of the 12 the enum takes.
//!
//! A pair event keeps its partner, the partner's image code (5 bits, as in
//! the neighbour lists) and the partner's stamp when the event was predicted,
//! of which the low 27 bits are kept: the event is stale when the partner's
//! stamp has moved on, and to pass for fresh it would have to move on by a
//! multiple of 2^27 events before this one falls due. Image codes 27-29,
//! which no pair uses (3D has 27 codes, 0-26, and a plane is 31), mark the
//! other kinds of event.

use super::neighbours::Image;

/// What a particle's scheduled event is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Next {
    Nothing,
    /// `stamp`: the partner's stamp when predicted (only its low 27 bits
    /// count: compare with [`Next::same_stamp`]).
    Pair {
        j: u32,
        stamp: u32,
        image: Image,
    },
    Wall {
        axis: u8,
        high: bool,
    },
    /// The particle reaches the edge of its neighbourhood.
    Renew,
}

const IMAGE_BITS: u32 = 5;
const IMAGES: u32 = (1 << IMAGE_BITS) - 1;
const NOTHING: u32 = 27;
const WALL: u32 = 28;
const RENEW: u32 = 29;

impl Next {
    /// Whether a pair event's stamp still matches the partner's stamp now.
    #[inline(always)]
    pub fn same_stamp(kept: u32, now: u32) -> bool {
        (kept ^ now) << IMAGE_BITS == 0
    }
}

/// A [`Next`] in 8 bytes: `who` is the partner (or a wall's axis and side),
/// `what` the stamp above the kind's 5 bits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Packed {
    who: u32,
    what: u32,
}

impl Packed {
    pub const NOTHING: Packed = Packed {
        who: 0,
        what: NOTHING,
    };

    #[inline(always)]
    pub fn pack(next: Next) -> Packed {
        match next {
            Next::Nothing => Packed::NOTHING,
            Next::Pair { j, stamp, image } => Packed {
                who: j,
                what: stamp << IMAGE_BITS | image as u32,
            },
            Next::Wall { axis, high } => Packed {
                who: (axis as u32) << 1 | high as u32,
                what: WALL,
            },
            Next::Renew => Packed {
                who: 0,
                what: RENEW,
            },
        }
    }

    #[inline(always)]
    pub fn unpack(self) -> Next {
        match self.what & IMAGES {
            NOTHING => Next::Nothing,
            WALL => Next::Wall {
                axis: (self.who >> 1) as u8,
                high: self.who & 1 != 0,
            },
            RENEW => Next::Renew,
            image => Next::Pair {
                j: self.who,
                stamp: self.what >> IMAGE_BITS,
                image: image as Image,
            },
        }
    }
}

impl Default for Packed {
    fn default() -> Self {
        Packed::NOTHING
    }
}

/// What the queue keeps of a particle's event beside its time: what it is,
/// and the particle's own stamp, which moves on whenever its motion changes.
/// 16 bytes, so that the queue's 32-byte records never straddle a line.
#[derive(Debug, Clone, Copy, Default)]
#[repr(align(16))]
pub(super) struct Event {
    pub next: Packed,
    pub stamp: u32,
}
const _: () = assert!(std::mem::size_of::<Event>() == 16);

#[cfg(test)]
mod tests {
    use super::*;

    /// Every kind of event comes back as it went in (a pair's stamp to its
    /// low 27 bits, which is all a stamp comparison looks at).
    #[test]
    fn every_event_round_trips_in_eight_bytes() {
        assert_eq!(std::mem::size_of::<Packed>(), 8);
        let mut events = vec![Next::Nothing, Next::Renew];
        for axis in 0..3 {
            for high in [false, true] {
                events.push(Next::Wall { axis, high });
            }
        }
        for image in (0..27).chain([31]) {
            for (j, stamp) in [(0, 0), (7, 5), (u32::MAX, (1 << 27) - 1)] {
                events.push(Next::Pair { j, stamp, image });
            }
        }
        for e in events {
            assert_eq!(Packed::pack(e).unpack(), e);
        }
        let wide = Next::Pair {
            j: 3,
            stamp: u32::MAX,
            image: 4,
        };
        let Next::Pair { stamp, .. } = Packed::pack(wide).unpack() else {
            panic!("a pair came back as something else");
        };
        assert!(Next::same_stamp(stamp, u32::MAX));
        assert!(!Next::same_stamp(stamp, u32::MAX - 1));
    }
}
