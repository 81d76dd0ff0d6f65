//! Reading a fuzz input front to back, shared by the targets (each uses what it needs).
#![allow(dead_code)]

/// The input, read front to back; zeros once it runs out.
pub struct Bytes<'a>(pub &'a [u8]);

impl Bytes<'_> {
    pub fn byte(&mut self) -> u8 {
        let (b, rest) = self.0.split_first().map_or((0, &[][..]), |(b, r)| (*b, r));
        self.0 = rest;
        b
    }

    /// One of `items`.
    pub fn pick<'b, T>(&mut self, items: &'b [T]) -> &'b T {
        &items[usize::from(self.byte()) % items.len()]
    }

    /// An f64: one of `nice` (values the target's inputs hold) scaled by 1 to 1.875 when the
    /// first byte is even, so that most inputs get past the checks; any bits when it is odd.
    pub fn f64_from(&mut self, nice: &[f64]) -> f64 {
        let tag = self.byte();
        if tag & 1 == 0 {
            return nice[usize::from(tag >> 1) % nice.len()] * (1.0 + f64::from(tag >> 5) / 8.0);
        }
        let mut b = [0u8; 8];
        for x in &mut b {
            *x = self.byte();
        }
        f64::from_le_bytes(b)
    }
}
