//! A small animated-GIF (GIF89a) encoder: one global palette of at most 256 colours, LZW
//! compression, looping forever. Enough for ridge animations, whose frames hold few colours;
//! written here so that no image crate beyond plotters' is needed.

use std::collections::HashMap;
use std::io::Write;

/// One RGB frame, 3 bytes a pixel, row by row.
pub type RgbFrame = Vec<u8>;

/// Encodes `frames` (each `width × height` RGB pixels) as a looping GIF, `delay_cs`
/// hundredths of a second per frame. Colours beyond the 256 most frequent are mapped to the
/// nearest of those (text anti-aliasing shades, mostly).
///
/// # Panics
/// When a frame's length is not `3 · width · height`, or a dimension is 0 or above 65535.
pub fn encode(
    out: &mut impl Write,
    width: u32,
    height: u32,
    frames: &[RgbFrame],
    delay_cs: u16,
) -> std::io::Result<()> {
    assert!(width > 0 && height > 0 && width <= 65535 && height <= 65535);
    let n = (width * height) as usize;
    for f in frames {
        assert_eq!(f.len(), 3 * n, "frame size");
    }
    let (palette, index) = palette(frames);
    out.write_all(b"GIF89a")?;
    out.write_all(&(width as u16).to_le_bytes())?;
    out.write_all(&(height as u16).to_le_bytes())?;
    // Global colour table of 256 entries, 8 bits of colour resolution.
    out.write_all(&[0xF7, 0, 0])?;
    let mut table = [0u8; 768];
    for (i, c) in palette.iter().enumerate() {
        table[3 * i..3 * i + 3].copy_from_slice(&rgb(*c));
    }
    out.write_all(&table)?;
    // Loop forever (NETSCAPE2.0 application extension).
    out.write_all(&[0x21, 0xFF, 0x0B])?;
    out.write_all(b"NETSCAPE2.0")?;
    out.write_all(&[0x03, 0x01, 0x00, 0x00, 0x00])?;
    let mut pixels = vec![0u8; n];
    for f in frames {
        // Graphic control: no disposal, the delay, no transparency.
        out.write_all(&[0x21, 0xF9, 0x04, 0x04])?;
        out.write_all(&delay_cs.to_le_bytes())?;
        out.write_all(&[0x00, 0x00])?;
        // Image descriptor: the whole screen, no local table.
        out.write_all(&[0x2C, 0, 0, 0, 0])?;
        out.write_all(&(width as u16).to_le_bytes())?;
        out.write_all(&(height as u16).to_le_bytes())?;
        out.write_all(&[0x00])?;
        for (p, px) in pixels.iter_mut().zip(f.chunks_exact(3)) {
            *p = index[&pack(px)];
        }
        out.write_all(&[8])?;
        let data = lzw(&pixels);
        for chunk in data.chunks(255) {
            out.write_all(&[chunk.len() as u8])?;
            out.write_all(chunk)?;
        }
        out.write_all(&[0x00])?;
    }
    out.write_all(&[0x3B])
}

fn pack(px: &[u8]) -> u32 {
    (px[0] as u32) << 16 | (px[1] as u32) << 8 | px[2] as u32
}

fn rgb(c: u32) -> [u8; 3] {
    [(c >> 16) as u8, (c >> 8) as u8, c as u8]
}

/// The palette (the ≤ 256 most frequent colours) and every colour's index in it.
fn palette(frames: &[RgbFrame]) -> (Vec<u32>, HashMap<u32, u8>) {
    let mut count: HashMap<u32, u64> = HashMap::new();
    for f in frames {
        for px in f.chunks_exact(3) {
            *count.entry(pack(px)).or_default() += 1;
        }
    }
    let mut by_freq: Vec<(u32, u64)> = count.iter().map(|(&c, &k)| (c, k)).collect();
    by_freq.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let palette: Vec<u32> = by_freq.iter().take(256).map(|&(c, _)| c).collect();
    let mut index = HashMap::with_capacity(count.len());
    for &(c, _) in &by_freq {
        let [r, g, b] = rgb(c);
        let nearest = palette
            .iter()
            .enumerate()
            .min_by_key(|&(_, &p)| {
                let [pr, pg, pb] = rgb(p);
                let d = |a: u8, b: u8| (a as i32 - b as i32).pow(2);
                d(r, pr) + d(g, pg) + d(b, pb)
            })
            .map(|(i, _)| i as u8)
            .unwrap_or(0);
        index.insert(c, nearest);
    }
    (palette, index)
}

/// Variable-length LZW of 8-bit indices as GIF wants it (minimum code size 8, clear code
/// first, a clear when the table is full, end-of-information last, bits LSB first).
fn lzw(pixels: &[u8]) -> Vec<u8> {
    const CLEAR: u16 = 256;
    const EOI: u16 = 257;
    struct Bits {
        out: Vec<u8>,
        acc: u32,
        n: u32,
    }
    impl Bits {
        fn put(&mut self, code: u16, size: u32) {
            self.acc |= (code as u32) << self.n;
            self.n += size;
            while self.n >= 8 {
                self.out.push(self.acc as u8);
                self.acc >>= 8;
                self.n -= 8;
            }
        }
    }
    let mut bits = Bits {
        out: Vec::new(),
        acc: 0,
        n: 0,
    };
    let mut dict: HashMap<(u16, u8), u16> = HashMap::new();
    let mut size = 9u32;
    let mut next = 258u16;
    bits.put(CLEAR, size);
    let Some((&first, rest)) = pixels.split_first() else {
        bits.put(EOI, size);
        if bits.n > 0 {
            bits.out.push(bits.acc as u8);
        }
        return bits.out;
    };
    let mut cur = first as u16;
    // Emits a code, then widens the codes once the next code to assign no longer fits.
    let emit = |bits: &mut Bits, code: u16, size: &mut u32, next: u16| {
        bits.put(code, *size);
        if next as u32 >= (1 << *size) && *size < 12 {
            *size += 1;
        }
    };
    for &k in rest {
        if let Some(&c) = dict.get(&(cur, k)) {
            cur = c;
            continue;
        }
        emit(&mut bits, cur, &mut size, next);
        dict.insert((cur, k), next);
        next += 1;
        if next == 4096 {
            bits.put(CLEAR, size);
            dict.clear();
            size = 9;
            next = 258;
        }
        cur = k as u16;
    }
    emit(&mut bits, cur, &mut size, next);
    bits.put(EOI, size);
    if bits.n > 0 {
        bits.out.push(bits.acc as u8);
    }
    bits.out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reference LZW decoder (GIF flavour), for round trips.
    fn unlzw(data: &[u8]) -> Vec<u8> {
        let mut pos = 0usize; // bit position
        let read = |pos: &mut usize, size: u32| -> u16 {
            let mut v = 0u32;
            for i in 0..size {
                let byte = data[(*pos + i as usize) / 8];
                let bit = (byte >> ((*pos + i as usize) % 8)) & 1;
                v |= (bit as u32) << i;
            }
            *pos += size as usize;
            v as u16
        };
        let mut out = Vec::new();
        let mut table: Vec<Vec<u8>> = Vec::new();
        let reset = |t: &mut Vec<Vec<u8>>| {
            t.clear();
            for i in 0..256 {
                t.push(vec![i as u8]);
            }
            t.push(vec![]);
            t.push(vec![]);
        };
        reset(&mut table);
        let mut size = 9u32;
        let mut prev: Option<Vec<u8>> = None;
        loop {
            let code = read(&mut pos, size);
            if code == 256 {
                reset(&mut table);
                size = 9;
                prev = None;
                continue;
            }
            if code == 257 {
                break;
            }
            let entry = if (code as usize) < table.len() {
                table[code as usize].clone()
            } else {
                let p = prev.clone().unwrap();
                let mut e = p.clone();
                e.push(p[0]);
                e
            };
            out.extend_from_slice(&entry);
            if let Some(p) = prev {
                if table.len() < 4096 {
                    let mut e = p.clone();
                    e.push(entry[0]);
                    table.push(e);
                }
            }
            if table.len() == (1 << size) && size < 12 {
                size += 1;
            }
            prev = Some(entry);
        }
        out
    }

    #[test]
    fn lzw_round_trips() {
        let mut x = 12345u32;
        let mut noisy = Vec::new();
        for _ in 0..200_000 {
            x = x.wrapping_mul(1_103_515_245).wrapping_add(12345);
            noisy.push(((x >> 16) % 7) as u8 * 30);
        }
        let flat = vec![3u8; 100_000];
        let ramp: Vec<u8> = (0..70_000u32).map(|i| (i % 256) as u8).collect();
        for data in [noisy, flat, ramp, vec![], vec![9]] {
            assert_eq!(unlzw(&lzw(&data)), data);
        }
    }

    #[test]
    fn gif_has_header_frames_and_trailer() {
        let f1 = vec![255u8; 3 * 4 * 3];
        let mut f2 = f1.clone();
        f2[0] = 0;
        let mut buf = Vec::new();
        encode(&mut buf, 4, 3, &[f1, f2], 10).unwrap();
        assert_eq!(&buf[..6], b"GIF89a");
        assert_eq!(*buf.last().unwrap(), 0x3B);
        assert_eq!(buf.windows(2).filter(|w| w == &[0x21, 0xF9]).count(), 2);
    }
}
