//! Shared checks of the figure tests: each figure rendered as SVG and PNG and checked
//! (size, title, labels, series colours; the PNG decoded by a minimal reader).
#![allow(dead_code)]

use polargen::plot::{render, Figure};
use std::path::PathBuf;

/// Directory for this test run's images (kept, so they can be inspected).
pub fn out_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("polargen-plot-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// (opening tag, trimmed content) of every `<text>` element of an SVG document.
pub fn svg_texts(svg: &str) -> Vec<(String, String)> {
    svg.split("<text")
        .skip(1)
        .filter_map(|part| {
            let (tag, rest) = part.split_once('>')?;
            let content = rest.split("</text>").next()?.trim().to_string();
            Some((tag.to_string(), content))
        })
        .collect()
}

/// Numeric attribute `name` of an SVG tag.
pub fn attr(tag: &str, name: &str) -> Option<f64> {
    tag.split(&format!(" {name}=\""))
        .nth(1)?
        .split('"')
        .next()?
        .parse()
        .ok()
}

/// SVG colour string of palette index `i` as plotters writes it.
pub fn svg_color(i: usize) -> &'static str {
    ["#1F77B4", "#D62728", "#2CA02C", "#FF7F0E"][i]
}

/// RGB of palette index `i`.
pub fn rgb(i: usize) -> [u8; 3] {
    [[31, 119, 180], [214, 39, 40], [44, 160, 44], [255, 127, 14]][i]
}

/// Renders `fig` as SVG and PNG under `name`, checks both, returns the SVG text.
pub fn render_and_check(fig: &Figure, name: &str, texts: &[&str], colors: &[usize]) -> String {
    let dir = out_dir();
    let svg_path = dir.join(format!("{name}.svg"));
    let png_path = dir.join(format!("{name}.png"));
    render(fig, &svg_path).expect("svg render");
    render(fig, &png_path).expect("png render");

    let svg = std::fs::read_to_string(&svg_path).expect("svg written");
    assert!(svg.len() > 10_000, "{name}.svg only {} bytes", svg.len());
    assert!(svg.starts_with("<svg"), "{name}.svg is not an SVG document");
    assert!(
        svg.trim_end().ends_with("</svg>"),
        "{name}.svg is truncated"
    );
    assert!(svg.contains(&fig.title), "{name}.svg lacks its title");
    for t in texts {
        assert!(svg.contains(t), "{name}.svg lacks text {t:?}");
    }
    for &c in colors {
        assert!(
            svg.contains(&format!("stroke=\"{}\"", svg_color(c))),
            "{name}.svg has no line in palette colour {c}"
        );
    }

    let png = std::fs::read(&png_path).expect("png written");
    assert!(png.len() > 20_000, "{name}.png only {} bytes", png.len());
    let img = png_decode::decode(&png).expect("png decodes");
    // grid: one row up to 3 panels, 4 as 2 × 2, 5 and 6 as 2 × 3
    let n = fig.panels.len() as u32;
    let cols = if n <= 3 {
        n
    } else {
        (f64::from(n)).sqrt().ceil() as u32
    };
    assert_eq!(img.width, 720 * cols, "{name}.png width");
    let rows = n.div_ceil(cols);
    assert!(
        img.height >= 50 + 520 * rows,
        "{name}.png height {}",
        img.height
    );
    let non_white = img.pixels.iter().filter(|p| **p != [255, 255, 255]).count();
    let fraction = non_white as f64 / img.pixels.len() as f64;
    assert!(
        fraction > 0.02,
        "{name}.png is nearly blank ({fraction:.4})"
    );
    for &c in colors {
        let n = img.pixels.iter().filter(|p| **p == rgb(c)).count();
        assert!(
            n > 200,
            "{name}.png has only {n} pixels of palette colour {c}"
        );
    }
    // Title text: dark anti-aliased glyph pixels in the title strip (font rendered).
    let dark_title = img.pixels[..(img.width * 50) as usize]
        .iter()
        .filter(|p| p.iter().all(|&v| v < 80))
        .count();
    assert!(
        dark_title > 300,
        "{name}.png title strip has {dark_title} dark pixels"
    );
    svg
}

/// Minimal PNG reader for the tests: zlib/DEFLATE (RFC 1950/1951) and PNG scanline filters
/// (PNG spec §9), 8-bit RGB or RGBA, non-interlaced — what plotters' encoder writes.
mod png_decode {
    /// Decoded image: RGB pixels row by row.
    pub struct Image {
        pub width: u32,
        pub height: u32,
        pub pixels: Vec<[u8; 3]>,
    }

    fn be32(b: &[u8]) -> u32 {
        u32::from_be_bytes([b[0], b[1], b[2], b[3]])
    }

    /// Decodes a PNG file.
    pub fn decode(png: &[u8]) -> Result<Image, String> {
        if png.len() < 8 || png[..8] != [0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A] {
            return Err("bad PNG signature".into());
        }
        let mut pos = 8;
        let (mut width, mut height, mut channels) = (0, 0, 0);
        let mut idat = Vec::new();
        while pos + 8 <= png.len() {
            let len = be32(&png[pos..]) as usize;
            let kind = &png[pos + 4..pos + 8];
            let data = png.get(pos + 8..pos + 8 + len).ok_or("truncated chunk")?;
            match kind {
                b"IHDR" => {
                    width = be32(data);
                    height = be32(&data[4..]);
                    if data[8] != 8 || data[12] != 0 {
                        return Err("only 8-bit non-interlaced PNGs".into());
                    }
                    channels = match data[9] {
                        2 => 3,
                        6 => 4,
                        c => return Err(format!("colour type {c} unsupported")),
                    };
                }
                b"IDAT" => idat.extend_from_slice(data),
                b"IEND" => break,
                _ => {}
            }
            pos += 12 + len;
        }
        if width == 0 || height == 0 {
            return Err("missing IHDR".into());
        }
        let raw = inflate(idat.get(2..).ok_or("empty IDAT")?)?;
        let stride = width as usize * channels;
        if raw.len() < (stride + 1) * height as usize {
            return Err("not enough image data".into());
        }
        let mut prev = vec![0u8; stride];
        let mut pixels = Vec::with_capacity((width * height) as usize);
        for row in 0..height as usize {
            let line = &raw[row * (stride + 1)..(row + 1) * (stride + 1)];
            let mut cur = line[1..].to_vec();
            for i in 0..stride {
                let a = if i >= channels {
                    cur[i - channels] as i16
                } else {
                    0
                };
                let b = prev[i] as i16;
                let c = if i >= channels {
                    prev[i - channels] as i16
                } else {
                    0
                };
                let pred = match line[0] {
                    0 => 0,
                    1 => a,
                    2 => b,
                    3 => (a + b) / 2,
                    4 => {
                        let p = a + b - c;
                        let (pa, pb, pc) = ((p - a).abs(), (p - b).abs(), (p - c).abs());
                        if pa <= pb && pa <= pc {
                            a
                        } else if pb <= pc {
                            b
                        } else {
                            c
                        }
                    }
                    f => return Err(format!("bad filter {f}")),
                };
                cur[i] = cur[i].wrapping_add(pred as u8);
            }
            pixels.extend(cur.chunks(channels).map(|p| [p[0], p[1], p[2]]));
            prev = cur;
        }
        Ok(Image {
            width,
            height,
            pixels,
        })
    }

    /// LSB-first bit reader over a DEFLATE stream.
    struct Bits<'a> {
        data: &'a [u8],
        pos: usize,
        bit: u32,
    }

    impl Bits<'_> {
        fn get(&mut self, n: u32) -> Result<u32, String> {
            let mut v = 0;
            for k in 0..n {
                let byte = *self.data.get(self.pos).ok_or("deflate stream ended")?;
                v |= (((byte >> self.bit) & 1) as u32) << k;
                self.bit += 1;
                if self.bit == 8 {
                    self.bit = 0;
                    self.pos += 1;
                }
            }
            Ok(v)
        }
    }

    /// Canonical Huffman code: number of codes per length and symbols in code order.
    struct Huffman {
        counts: [u16; 16],
        symbols: Vec<u16>,
    }

    impl Huffman {
        fn new(lengths: &[u8]) -> Self {
            let mut counts = [0u16; 16];
            for &l in lengths {
                counts[l as usize] += 1;
            }
            counts[0] = 0;
            let mut offsets = [0u16; 16];
            for l in 1..16 {
                offsets[l] = offsets[l - 1] + counts[l - 1];
            }
            let mut symbols = vec![0; lengths.len()];
            for (s, &l) in lengths.iter().enumerate() {
                if l != 0 {
                    symbols[offsets[l as usize] as usize] = s as u16;
                    offsets[l as usize] += 1;
                }
            }
            Self { counts, symbols }
        }

        fn decode(&self, bits: &mut Bits) -> Result<u16, String> {
            let (mut code, mut first, mut index) = (0i32, 0i32, 0i32);
            for len in 1..16 {
                code |= bits.get(1)? as i32;
                let count = self.counts[len] as i32;
                if code - first < count {
                    return Ok(self.symbols[(index + code - first) as usize]);
                }
                index += count;
                first = (first + count) << 1;
                code <<= 1;
            }
            Err("bad Huffman code".into())
        }
    }

    const LEN_BASE: [u16; 29] = [
        3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115,
        131, 163, 195, 227, 258,
    ];
    const LEN_EXTRA: [u8; 29] = [
        0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
    ];
    const DIST_BASE: [u16; 30] = [
        1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
        2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577,
    ];
    const DIST_EXTRA: [u8; 30] = [
        0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12,
        13, 13,
    ];

    /// Inflates a raw DEFLATE stream (RFC 1951).
    pub fn inflate(data: &[u8]) -> Result<Vec<u8>, String> {
        let mut bits = Bits {
            data,
            pos: 0,
            bit: 0,
        };
        let mut out: Vec<u8> = Vec::new();
        loop {
            let last = bits.get(1)?;
            match bits.get(2)? {
                0 => {
                    if bits.bit != 0 {
                        bits.bit = 0;
                        bits.pos += 1;
                    }
                    let p = bits.pos;
                    let len = u16::from_le_bytes([data[p], data[p + 1]]) as usize;
                    out.extend_from_slice(data.get(p + 4..p + 4 + len).ok_or("stored block")?);
                    bits.pos = p + 4 + len;
                }
                1 => {
                    let mut l = [8u8; 288];
                    l[144..256].fill(9);
                    l[256..280].fill(7);
                    block(
                        &mut bits,
                        &mut out,
                        &Huffman::new(&l),
                        &Huffman::new(&[5; 30]),
                    )?;
                }
                2 => {
                    let hlit = bits.get(5)? as usize + 257;
                    let hdist = bits.get(5)? as usize + 1;
                    let hclen = bits.get(4)? as usize + 4;
                    const ORDER: [usize; 19] = [
                        16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15,
                    ];
                    let mut cl = [0u8; 19];
                    for &o in &ORDER[..hclen] {
                        cl[o] = bits.get(3)? as u8;
                    }
                    let code_lengths = Huffman::new(&cl);
                    let mut lengths = Vec::with_capacity(hlit + hdist);
                    while lengths.len() < hlit + hdist {
                        match code_lengths.decode(&mut bits)? {
                            s @ 0..=15 => lengths.push(s as u8),
                            16 => {
                                let prev = *lengths.last().ok_or("repeat without length")?;
                                let n = 3 + bits.get(2)?;
                                lengths.extend(std::iter::repeat_n(prev, n as usize));
                            }
                            17 => {
                                let n = 3 + bits.get(3)?;
                                lengths.extend(std::iter::repeat_n(0, n as usize));
                            }
                            _ => {
                                let n = 11 + bits.get(7)?;
                                lengths.extend(std::iter::repeat_n(0, n as usize));
                            }
                        }
                    }
                    let lit = Huffman::new(&lengths[..hlit]);
                    let dist = Huffman::new(&lengths[hlit..]);
                    block(&mut bits, &mut out, &lit, &dist)?;
                }
                _ => return Err("bad block type".into()),
            }
            if last == 1 {
                return Ok(out);
            }
        }
    }

    /// Decodes one Huffman-coded block.
    fn block(
        bits: &mut Bits,
        out: &mut Vec<u8>,
        lit: &Huffman,
        dist: &Huffman,
    ) -> Result<(), String> {
        loop {
            let sym = lit.decode(bits)? as usize;
            if sym < 256 {
                out.push(sym as u8);
            } else if sym == 256 {
                return Ok(());
            } else {
                let i = sym - 257;
                let len = *LEN_BASE.get(i).ok_or("bad length")? as usize
                    + bits.get(LEN_EXTRA[i] as u32)? as usize;
                let d = dist.decode(bits)? as usize;
                let back = *DIST_BASE.get(d).ok_or("bad distance")? as usize
                    + bits.get(DIST_EXTRA[d] as u32)? as usize;
                let start = out.len().checked_sub(back).ok_or("distance too far")?;
                for k in 0..len {
                    out.push(out[start + k]);
                }
            }
        }
    }
}
