//! Pixel geometry of the line charts: rectangles, dash patterns, and the
//! placement of text beside points and at line ends so that no two labels
//! overlap and none covers a marker.

/// An axis-aligned rectangle in pixels, `x0 <= x1`, `y0 <= y1` (y down).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct PxRect {
    pub(super) x0: i32,
    pub(super) y0: i32,
    pub(super) x1: i32,
    pub(super) y1: i32,
}

impl PxRect {
    /// The rectangle `w × h` whose left edge is `x0` and whose centre is at
    /// height `cy`.
    pub(super) fn left_centre(x0: i32, cy: i32, w: i32, h: i32) -> PxRect {
        PxRect {
            x0,
            y0: cy - h / 2,
            x1: x0 + w,
            y1: cy - h / 2 + h,
        }
    }

    /// The square of half-size `r` around `p`.
    pub(super) fn around(p: (i32, i32), r: i32) -> PxRect {
        PxRect {
            x0: p.0 - r,
            y0: p.1 - r,
            x1: p.0 + r,
            y1: p.1 + r,
        }
    }

    /// Whether the two share any interior.
    pub(super) fn overlaps(&self, o: &PxRect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// Whether `self` lies wholly within `o`.
    pub(super) fn inside(&self, o: &PxRect) -> bool {
        self.x0 >= o.x0 && self.x1 <= o.x1 && self.y0 >= o.y0 && self.y1 <= o.y1
    }

    pub(super) fn contains(&self, p: (i32, i32)) -> bool {
        p.0 >= self.x0 && p.0 <= self.x1 && p.1 >= self.y0 && p.1 <= self.y1
    }

    pub(super) fn centre_y(&self) -> i32 {
        (self.y0 + self.y1) / 2
    }
}

/// Splits a polyline into the pieces drawn by a dash `pattern` (lengths in
/// pixels, alternately drawn and skipped); an empty pattern is one solid
/// piece.
pub(super) fn dashes(points: &[(i32, i32)], pattern: &[u32]) -> Vec<Vec<(i32, i32)>> {
    if pattern.is_empty() || pattern.iter().all(|&d| d == 0) || points.len() < 2 {
        return vec![points.to_vec()];
    }
    let mut pieces = Vec::new();
    let mut current: Vec<(i32, i32)> = Vec::new();
    let (mut k, mut left) = (0usize, f64::from(pattern[0].max(1)));
    let on = |k: usize| k % 2 == 0;
    for w in points.windows(2) {
        let (a, b) = (
            (f64::from(w[0].0), f64::from(w[0].1)),
            (f64::from(w[1].0), f64::from(w[1].1)),
        );
        let length = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        let at = |t: f64| -> (i32, i32) {
            let f = if length > 0.0 { t / length } else { 0.0 };
            (
                (a.0 + f * (b.0 - a.0)).round() as i32,
                (a.1 + f * (b.1 - a.1)).round() as i32,
            )
        };
        let mut t = 0.0;
        if on(k) && current.is_empty() {
            current.push(at(0.0));
        }
        while length - t > left {
            t += left;
            if on(k) {
                current.push(at(t));
                pieces.push(std::mem::take(&mut current));
            } else {
                current = vec![at(t)];
            }
            k = (k + 1) % pattern.len();
            left = f64::from(pattern[k].max(1));
        }
        left -= length - t;
        if on(k) {
            current.push(at(length));
        }
    }
    if current.len() >= 2 {
        pieces.push(current);
    }
    pieces
}

/// Points every few pixels along a polyline: what a label should not cover.
pub(super) fn samples(points: &[(i32, i32)], every: f64) -> Vec<(i32, i32)> {
    let mut out: Vec<(i32, i32)> = points.first().copied().into_iter().collect();
    for w in points.windows(2) {
        let (dx, dy) = (f64::from(w[1].0 - w[0].0), f64::from(w[1].1 - w[0].1));
        let steps = ((dx * dx + dy * dy).sqrt() / every).ceil().max(1.0) as i32;
        for s in 1..=steps {
            let f = f64::from(s) / f64::from(steps);
            out.push((
                w[0].0 + (f * dx).round() as i32,
                w[0].1 + (f * dy).round() as i32,
            ));
        }
    }
    out
}

/// Places labels one at a time, each in the first of its candidate spots
/// that stays within bounds and overlaps no label placed before and no
/// marker; among those, a spot that covers no line is preferred.
pub(super) struct Placer {
    pub(super) bounds: PxRect,
    pub(super) taken: Vec<PxRect>,
    pub(super) markers: Vec<PxRect>,
    pub(super) lines: Vec<(i32, i32)>,
}

impl Placer {
    /// Whether `r` is within bounds and clear of labels and markers (and of
    /// lines if `strict`).
    fn free(&self, r: &PxRect, strict: bool) -> bool {
        r.inside(&self.bounds)
            && !self.taken.iter().any(|t| t.overlaps(r))
            && !self.markers.iter().any(|m| m.overlaps(r))
            && (!strict || !self.lines.iter().any(|&p| r.contains(p)))
    }

    /// The first candidate clear of everything, else the first clear of
    /// labels and markers; it is then taken.
    pub(super) fn place(&mut self, candidates: &[PxRect]) -> Option<PxRect> {
        self.place_near(&[candidates.to_vec()])
    }

    /// [`Placer::place`] over groups of candidates, nearest group first: a
    /// near spot that crosses a line beats a far one that does not.
    pub(super) fn place_near(&mut self, groups: &[Vec<PxRect>]) -> Option<PxRect> {
        let chosen = groups.iter().find_map(|candidates| {
            candidates
                .iter()
                .find(|r| self.free(r, true))
                .or_else(|| candidates.iter().find(|r| self.free(r, false)))
                .copied()
        })?;
        self.taken.push(chosen);
        Some(chosen)
    }
}

/// Spots for a `w × h` label beside a point, in three rings: above, below,
/// right, left and the diagonals, at a gap `gap` from a marker of half-size
/// `r`, then the same twice and three times as far.
pub(super) fn around_point(p: (i32, i32), r: i32, w: i32, h: i32, gap: i32) -> Vec<Vec<PxRect>> {
    let mut rings = Vec::new();
    for ring in 1..=3 {
        let mut out = Vec::new();
        let d = r + gap * ring + 6 * (ring - 1);
        let spots = [
            (p.0 - w / 2, p.1 - d - h),
            (p.0 - w / 2, p.1 + d),
            (p.0 + d, p.1 - h / 2),
            (p.0 - d - w, p.1 - h / 2),
            (p.0 + d - 2, p.1 - d - h + 4),
            (p.0 + d - 2, p.1 + d - 4),
            (p.0 - d - w + 2, p.1 - d - h + 4),
            (p.0 - d - w + 2, p.1 + d - 4),
        ];
        out.extend(spots.iter().map(|&(x0, y0)| PxRect {
            x0,
            y0,
            x1: x0 + w,
            y1: y0 + h,
        }));
        rings.push(out);
    }
    rings
}

/// Spots for a line-end label: at its left edge `x0`, centred at `cy`, then
/// shifted up and down a few pixels at a time, nearest first, within
/// `y_lo..y_hi`.
pub(super) fn beside_end(x0: i32, cy: i32, w: i32, h: i32, y_lo: i32, y_hi: i32) -> Vec<PxRect> {
    let mut out = vec![PxRect::left_centre(x0, cy, w, h)];
    let reach = (y_hi - y_lo).max(0);
    let mut d = 3;
    while d <= reach {
        out.push(PxRect::left_centre(x0, cy - d, w, h));
        out.push(PxRect::left_centre(x0, cy + d, w, h));
        d += 3;
    }
    out
}

/// Centres for labels of height `h` wanted at centres `desired` (sorted, top
/// first): in the same order, none overlapping, each as near its wish as
/// the others allow (runs that would overlap are moved as one block,
/// centred on their wishes), all within `lo..hi` where they fit.
pub(super) fn stack(desired: &[i32], h: i32, lo: i32, hi: i32) -> Vec<i32> {
    // Blocks of consecutive labels: (first index, count, top).
    let mut blocks: Vec<(usize, usize, f64)> = Vec::new();
    let h_f = f64::from(h);
    let clamp = |top: f64, count: usize| -> f64 {
        let max_top = f64::from(hi) - count as f64 * h_f;
        top.min(max_top).max(f64::from(lo))
    };
    for (i, &d) in desired.iter().enumerate() {
        blocks.push((i, 1, clamp(f64::from(d) - h_f / 2.0, 1)));
        while blocks.len() > 1 {
            let (first, count, top) = blocks[blocks.len() - 1];
            let (pfirst, pcount, ptop) = blocks[blocks.len() - 2];
            if ptop + pcount as f64 * h_f <= top {
                break;
            }
            let n = pcount + count;
            let wish: f64 = (pfirst..first + count)
                .map(|j| f64::from(desired[j]) - h_f / 2.0 - (j - pfirst) as f64 * h_f)
                .sum::<f64>()
                / n as f64;
            blocks.pop();
            blocks.pop();
            blocks.push((pfirst, n, clamp(wish, n)));
        }
    }
    let mut out = Vec::with_capacity(desired.len());
    for (_, count, top) in blocks {
        for k in 0..count {
            out.push((top + k as f64 * h_f + h_f / 2.0).round() as i32);
        }
    }
    out
}
