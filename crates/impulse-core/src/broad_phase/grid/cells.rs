//! Step 2 of the grid: the counting sort of the gridded discs into cells,
//! by row and then each row by column (see the parent module), serially or
//! with each pool thread on its own run of discs and of bands of rows.

use super::{Band, Grid, Layout, BIG};
use crate::broad_phase::Disc;
#[cfg(feature = "parallel")]
use crate::parallel::{BAND_ROWS, CHUNK};
use std::ops::Range;

impl Grid {
    /// Counting sort of the gridded discs by cell into `sorted` and
    /// `starts`, each disc keeping its cell in `tag`. Two passes, so that
    /// memory is touched in order rather than at random: by row (a few
    /// hundred output streams), then each row, small enough to stay in
    /// cache, by column through `row_buf`.
    pub(super) fn sort_into_cells(&mut self, layout: &Layout) {
        let (nx, ny) = (layout.nx, layout.ny);
        let parts = crate::parallel::pool_or_here!(
            self.parallel && self.big.is_empty(),
            { crate::parallel::threads() },
            { 1 }
        );
        let longest = if parts > 1 {
            self.sort_into_rows_in_parts(layout, parts)
        } else {
            self.sort_into_rows(layout)
        };
        // Row r is sorted[row_starts[r]..row_starts[r + 1]]. Sort each by
        // column, band by band of rows; a row's cells end at starts[1..]
        // (each row's counts are zeroed as it is sorted).
        self.starts.resize(nx * ny + 1, 0);
        self.starts[0] = 0;
        self.band_rows.clear();
        crate::parallel::pool_or_here!(
            self.parallel,
            {
                let threads = crate::parallel::threads().max(1);
                let total = u64::from(self.row_starts[ny]);
                balanced_bands(&self.row_starts[..ny], total, threads, &mut self.band_rows);
            },
            {
                self.band_rows.extend([0, ny]);
            }
        );
        let bands = self.band_rows.len() - 1;
        self.bands.resize_with(bands, Band::default);
        for band in &mut self.bands {
            band.row_buf.resize(longest as usize, Disc::default());
            band.cursor.resize(nx, 0);
        }
        let row_starts = &self.row_starts;
        crate::parallel::pool_or_here!(
            bands > 1,
            {
                // Thread k sorts the rows of its run of bands, the run it
                // then sweeps (`on_each_part` over the bands).
                use crate::parallel::{spans_of, split_by, threads};
                let runs = spans_of(bands, 1, threads());
                let band_rows = &self.band_rows;
                let rows: Vec<Range<usize>> = runs
                    .iter()
                    .map(|run| band_rows[run.start]..band_rows[run.end])
                    .collect();
                let at = |r: usize| row_starts[r] as usize;
                let discs: Vec<_> = rows.iter().map(|r| at(r.start)..at(r.end)).collect();
                let cells: Vec<_> = rows.iter().map(|r| r.start * nx..r.end * nx).collect();
                let sorted = split_by(&mut self.sorted, &discs);
                let ends = split_by(&mut self.starts[1..], &cells);
                let scratch = split_by(&mut self.bands, &runs);
                let work: Vec<_> = rows
                    .into_iter()
                    .zip(sorted)
                    .zip(ends.into_iter().zip(scratch))
                    .map(|((rows, sorted), (ends, bands))| (rows, sorted, ends, bands.first_mut()))
                    .collect();
                crate::parallel::on_each_thread(work, |(rows, sorted, ends, band)| {
                    if let Some(band) = band {
                        sort_rows(layout, rows, row_starts, sorted, ends, band);
                    }
                });
            },
            {
                sort_rows(
                    layout,
                    0..ny,
                    row_starts,
                    &mut self.sorted,
                    &mut self.starts[1..],
                    &mut self.bands[0],
                );
            }
        );
    }

    /// Sorts the gridded discs into `sorted` row by row, in their order
    /// within each row (a counting sort on the row, each disc's row kept in
    /// its `tag`, [`BIG`] for a big one); `row_starts[r]` is then where row
    /// `r` begins, for `r` up to `ny`. Returns the longest row's length.
    fn sort_into_rows(&mut self, layout: &Layout) -> u32 {
        let ny = layout.ny;
        self.row_starts.clear();
        self.row_starts.resize(ny + 2, 0);
        let mut big = self.big.iter().peekable();
        for (k, d) in self.discs.iter_mut().enumerate() {
            if big.peek() == Some(&&(k as u32)) {
                big.next();
                d.tag = BIG;
            } else {
                let cy = layout.row(d);
                d.tag = cy as u32;
                self.row_starts[cy + 2] += 1;
            }
        }
        let (mut total, mut longest) = (0, 0);
        for s in self.row_starts.iter_mut() {
            longest = longest.max(*s);
            total += *s;
            *s = total;
        }
        // row_starts[r + 1] is now where row r begins; use it as the cursor.
        // (Every slot is written below, so the buffers are not cleared.)
        self.sorted.resize(total as usize, Disc::default());
        for d in &self.discs {
            if d.tag != BIG {
                let slot = &mut self.row_starts[d.tag as usize + 1];
                self.sorted[*slot as usize] = *d;
                *slot += 1;
            }
        }
        longest
    }

    /// [`Grid::sort_into_rows`] on rayon's pool, without big discs: the
    /// discs cut into `parts` runs, each run's rows counted and its discs
    /// placed on its own thread, each row's discs from the first run, then
    /// the second…, so that every disc lands where the serial sort puts it.
    #[cfg(feature = "parallel")]
    fn sort_into_rows_in_parts(&mut self, layout: &Layout, parts: usize) -> u32 {
        let ny = layout.ny;
        // Thread k takes the discs it gathered (`on_each_part`'s runs of
        // chunks; they line up unless gathering skipped a disc that was not
        // finite, which costs only where the discs are cached). Any runs in
        // order give the same rows.
        let spans = crate::parallel::spans_of(self.discs.len(), CHUNK, parts);
        let runs = crate::parallel::split_by(&mut self.discs, &spans);
        let counts: Vec<Vec<u32>> = crate::parallel::on_each_thread(runs, |discs| {
            let mut count = vec![0u32; ny];
            for d in discs {
                let cy = layout.row(d);
                d.tag = cy as u32;
                count[cy] += 1;
            }
            count
        });
        self.row_starts.clear();
        self.row_starts.resize(ny + 2, 0);
        let (mut total, mut longest) = (0u32, 0u32);
        for r in 0..ny {
            self.row_starts[r] = total;
            let row: u32 = counts.iter().map(|count| count[r]).sum();
            longest = longest.max(row);
            total += row;
        }
        self.row_starts[ny] = total;
        self.row_starts[ny + 1] = total;
        self.sorted.resize(total as usize, Disc::default());
        // Each run's stretch of each row, row by row, run by run.
        let mut stretches: Vec<Vec<&mut [Disc]>> =
            (0..parts).map(|_| Vec::with_capacity(ny)).collect();
        let mut rest = &mut self.sorted[..];
        for r in 0..ny {
            for (part, count) in counts.iter().enumerate() {
                let (stretch, after) = std::mem::take(&mut rest).split_at_mut(count[r] as usize);
                stretches[part].push(stretch);
                rest = after;
            }
        }
        let runs = spans.iter().map(|span| &self.discs[span.clone()]);
        let work: Vec<_> = runs.zip(stretches).collect();
        crate::parallel::on_each_thread(work, |(discs, mut rows)| {
            for d in discs {
                let row = &mut rows[d.tag as usize];
                if let Some((slot, after)) = std::mem::take(row).split_first_mut() {
                    *slot = *d;
                    *row = after;
                }
            }
        });
        longest
    }

    #[cfg(not(feature = "parallel"))]
    fn sort_into_rows_in_parts(&mut self, layout: &Layout, _parts: usize) -> u32 {
        self.sort_into_rows(layout)
    }
}

/// Sorts rows `rows` by column: `sorted` holds their discs (row `r` at
/// `row_starts[r]..row_starts[r + 1]`, counted from the first row's start),
/// `ends` gets the end of each of their cells; `band` is the scratch.
fn sort_rows(
    layout: &Layout,
    rows: Range<usize>,
    row_starts: &[u32],
    sorted: &mut [Disc],
    ends: &mut [u32],
    band: &mut Band,
) {
    let nx = layout.nx;
    let Band {
        row_buf, cursor, ..
    } = band;
    let offset = row_starts[rows.start];
    for (r, ends) in rows.zip(ends.chunks_mut(nx)) {
        let (first, end) = (row_starts[r], row_starts[r + 1]);
        let row = &mut sorted[(first - offset) as usize..(end - offset) as usize];
        let base = r * nx;
        // Count into ends[c], then turn the counts into ends.
        ends.fill(0);
        for d in row.iter_mut() {
            let cx = layout.column(d);
            d.tag = (base + cx) as u32;
            ends[cx] += 1;
        }
        let mut at = 0;
        for (end, cursor) in ends.iter_mut().zip(cursor.iter_mut()) {
            *cursor = at;
            at += *end;
            *end = first + at;
        }
        for d in row.iter() {
            let slot = &mut cursor[d.tag as usize - base];
            row_buf[*slot as usize] = *d;
            *slot += 1;
        }
        row.copy_from_slice(&row_buf[..row.len()]);
    }
}

/// Cuts rows `0..row_starts.len()` into bands for `threads` threads into
/// `band_rows` (band b is rows `band_rows[b]..band_rows[b + 1]`): the
/// same number of bands per thread, each of at most [`BAND_ROWS`] rows, and
/// the rows of each thread's run of bands holding about `total / threads`
/// discs (`row_starts[r]`: the discs in rows before `r`), so that a pile
/// at the bottom of the box is shared out like an even gas.
#[cfg(feature = "parallel")]
fn balanced_bands(row_starts: &[u32], total: u64, threads: usize, band_rows: &mut Vec<usize>) {
    let ny = row_starts.len();
    let threads = threads.max(1) as u64;
    // Thread k's rows begin at the first row with a k-th of the discs below it.
    let splits: Vec<usize> = (0..=threads)
        .map(|k| match k {
            k if k == threads => ny,
            k => row_starts.partition_point(|&s| u64::from(s) * threads < total * k),
        })
        .collect();
    let per_thread = splits
        .windows(2)
        .map(|w| (w[1] - w[0]).div_ceil(BAND_ROWS))
        .max()
        .unwrap_or(1)
        .max(1);
    band_rows.clear();
    for w in splits.windows(2) {
        band_rows.extend((0..per_thread).map(|j| w[0] + (w[1] - w[0]) * j / per_thread));
    }
    band_rows.push(ny);
}

#[cfg(all(test, feature = "parallel"))]
mod tests {
    use super::balanced_bands;
    use crate::parallel::BAND_ROWS;

    /// `row_starts` of rows holding `counts` discs, and the total.
    fn starts(counts: &[u32]) -> (Vec<u32>, u64) {
        let mut total = 0;
        let starts = counts
            .iter()
            .map(|&c| {
                total += c;
                total - c
            })
            .collect();
        (starts, u64::from(total))
    }

    #[test]
    fn bands_cover_the_rows_and_share_the_discs_out_evenly() {
        let shapes: Vec<(&str, Vec<u32>)> = vec![
            ("even gas", vec![30; 341]),
            (
                "pile at the bottom",
                (0..200).map(|r| if r < 40 { 50 } else { 0 }).collect(),
            ),
            (
                "one full row",
                (0..50).map(|r| if r == 7 { 1000 } else { 0 }).collect(),
            ),
            ("empty", vec![0; 20]),
            ("one row", vec![5]),
        ];
        for (what, counts) in shapes {
            let (row_starts, total) = starts(&counts);
            for threads in [1, 2, 3, 16] {
                let mut bands = Vec::new();
                balanced_bands(&row_starts, total, threads, &mut bands);
                let ny = counts.len();
                assert_eq!((bands[0], *bands.last().unwrap()), (0, ny), "{what}");
                assert!(bands
                    .windows(2)
                    .all(|w| w[0] <= w[1] && w[1] - w[0] <= BAND_ROWS));
                let count = bands.len() - 1;
                assert_eq!(count % threads, 0, "{what}: the same bands per thread");
                let per = count / threads;
                // Each thread's discs: no more than a fair share plus one row's.
                let widest = u64::from(counts.iter().copied().max().unwrap_or(0));
                for k in 0..threads {
                    let rows = bands[k * per]..bands[(k + 1) * per];
                    let discs: u64 = counts[rows].iter().map(|&c| u64::from(c)).sum();
                    assert!(
                        discs <= total.div_ceil(threads as u64) + widest,
                        "{what}, {threads} threads: thread {k} has {discs} of {total}"
                    );
                }
            }
        }
    }
}
