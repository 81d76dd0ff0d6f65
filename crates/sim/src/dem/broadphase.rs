//! Candidate contact pairs by sort-and-sweep on the x axis.
//!
//! The sweep order is kept from step to step and repaired by insertion sort, which costs
//! O(N) when bodies have moved little (the usual case with a small time step) and never
//! worse than the O(N²) of a full re-sort of a reversed list. Pairs are emitted sorted by
//! `(a, b)` with `a < b`, so everything downstream is independent of the sweep order and
//! runs are bit-reproducible.

use super::geometry::Aabb;

/// Sort-and-sweep broad phase with persistent order and output buffers.
#[derive(Clone, Debug, Default)]
pub struct SweepAndPrune {
    order: Vec<u32>,
    pairs: Vec<u64>,
}

/// Packs a pair `a < b` into a sortable key.
#[inline]
pub fn pair_key(a: u32, b: u32) -> u64 {
    ((a as u64) << 32) | b as u64
}

/// Unpacks a key made by [`pair_key`].
#[inline]
pub fn unpack(k: u64) -> (u32, u32) {
    ((k >> 32) as u32, k as u32)
}

impl SweepAndPrune {
    /// Pairs of bodies whose boxes overlap, as sorted keys from [`pair_key`]. `skip(a, b)`
    /// removes pairs that need no contact test (two held bodies, joined neighbours).
    pub fn pairs(&mut self, aabb: &[Aabb], mut skip: impl FnMut(u32, u32) -> bool) -> &[u64] {
        let n = aabb.len() as u32;
        if self.order.len() != n as usize {
            // Bodies were added or removed: rebuild the order (new bodies at the end).
            self.order.retain(|&i| i < n);
            let mut seen = vec![false; n as usize];
            for &i in &self.order {
                seen[i as usize] = true;
            }
            for i in 0..n {
                if !seen[i as usize] {
                    self.order.push(i);
                }
            }
        }
        // Insertion sort on min.x: cheap for nearly sorted input, deterministic.
        let o = &mut self.order;
        for k in 1..o.len() {
            let cur = o[k];
            let key = aabb[cur as usize].min.x;
            let mut j = k;
            while j > 0 && aabb[o[j - 1] as usize].min.x > key {
                o[j] = o[j - 1];
                j -= 1;
            }
            o[j] = cur;
        }
        self.pairs.clear();
        for k in 0..o.len() {
            let i = o[k];
            let bi = &aabb[i as usize];
            for &j in &o[k + 1..] {
                let bj = &aabb[j as usize];
                if bj.min.x > bi.max.x {
                    break;
                }
                if bj.min.y <= bi.max.y && bi.min.y <= bj.max.y {
                    let (a, b) = if i < j { (i, j) } else { (j, i) };
                    if !skip(a, b) {
                        self.pairs.push(pair_key(a, b));
                    }
                }
            }
        }
        self.pairs.sort_unstable();
        &self.pairs
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::geometry::V2;

    fn bx(x0: f64, y0: f64, x1: f64, y1: f64) -> Aabb {
        Aabb {
            min: V2::new(x0, y0),
            max: V2::new(x1, y1),
        }
    }

    #[test]
    fn finds_exactly_the_overlapping_boxes() {
        // A deterministic scatter of boxes, checked against the all-pairs answer.
        let mut boxes = Vec::new();
        let mut s: u64 = 12345;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..300 {
            let (x, y) = (rnd() * 20.0, rnd() * 5.0);
            boxes.push(bx(x, y, x + 0.1 + rnd() * 0.5, y + 0.1 + rnd() * 0.5));
        }
        let mut sap = SweepAndPrune::default();
        let got: Vec<u64> = sap.pairs(&boxes, |_, _| false).to_vec();
        let mut want = Vec::new();
        for a in 0..boxes.len() {
            for b in a + 1..boxes.len() {
                if boxes[a].overlaps(&boxes[b]) {
                    want.push(pair_key(a as u32, b as u32));
                }
            }
        }
        assert_eq!(got, want);
        assert!(!want.is_empty());
        // Move everything and ask again: the persistent order is repaired.
        for b in boxes.iter_mut() {
            b.min.x = 20.0 - b.min.x;
            b.max.x = b.min.x + 0.3;
        }
        let got: Vec<u64> = sap.pairs(&boxes, |a, _| a == 0).to_vec();
        let want: Vec<u64> = (0..boxes.len())
            .flat_map(|a| (a + 1..boxes.len()).map(move |b| (a, b)))
            .filter(|&(a, b)| a != 0 && boxes[a].overlaps(&boxes[b]))
            .map(|(a, b)| pair_key(a as u32, b as u32))
            .collect();
        assert_eq!(got, want);
    }
}
