//! Where everything of a chart goes, in pixels of the image, before either
//! rendering draws it: the axes and plot area, each series' points, and
//! every label (line ends, point texts, the floor's name) placed clear of
//! the others ([`place`](super::place) finds the spots).

use super::*;

/// What a placed label is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum LabelKind {
    /// A series' name at its last point.
    End,
    /// Text beside one point.
    Point,
    /// The floor's label.
    Floor,
}

/// A label with its place: text drawn left-aligned in `rect` (padding
/// included), in `colour`, and a thin leader line from the point it belongs
/// to if it had to move away.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Placed {
    pub(super) kind: LabelKind,
    pub(super) text: String,
    pub(super) size: f64,
    pub(super) rect: PxRect,
    pub(super) colour: RGBColor,
    pub(super) leader: Option<((i32, i32), (i32, i32))>,
}

/// Horizontal padding inside a label's box (px).
pub(super) const PAD: i32 = 4;

/// Everything both renderings draw, in pixels of the image.
pub(super) struct Plan {
    pub(super) x: Axis,
    pub(super) y: Axis,
    /// The plot area.
    pub(super) plot: PxRect,
    /// Per series: each drawable point in pixels (`None` where skipped).
    pub(super) points: Vec<Vec<Option<(i32, i32)>>>,
    pub(super) highlight: Vec<Option<(i32, i32)>>,
    /// The floor's height in pixels.
    pub(super) floor: Option<i32>,
    pub(super) labels: Vec<Placed>,
    /// The legend's box, if there is a legend.
    pub(super) legend: Option<PxRect>,
}

/// Runs of consecutive drawable points.
pub(super) fn runs(points: &[Option<(i32, i32)>]) -> Vec<Vec<(i32, i32)>> {
    let mut runs = vec![Vec::new()];
    for p in points {
        match p {
            Some(p) => {
                if let Some(run) = runs.last_mut() {
                    run.push(*p);
                }
            }
            None => runs.push(Vec::new()),
        }
    }
    runs.retain(|r| !r.is_empty());
    runs
}

/// A colour darkened for text on white (pale ones would not read).
pub(super) fn text_colour(c: RGBColor) -> RGBColor {
    let f = |v: u8| (f64::from(v) * 0.72).round() as u8;
    RGBColor(f(c.0), f(c.1), f(c.2))
}

impl Series {
    pub(super) fn colour_at(&self, i: usize) -> RGBColor {
        PALETTE[self.colour.unwrap_or(i) % PALETTE.len()]
    }

    pub(super) fn marker_at(&self, i: usize) -> Marker {
        MARKERS[self.marker.unwrap_or(i) % MARKERS.len()]
    }

    pub(super) fn marker_radius(&self) -> i32 {
        if self.hollow {
            HOLLOW_SIZE
        } else {
            MARKER_SIZE
        }
    }
}

impl Plan {
    pub(super) fn new(chart: &Chart) -> Plan {
        let all = || {
            chart
                .series
                .iter()
                .chain(chart.highlight)
                .flat_map(|s| &s.points)
        };
        let floor_y = chart.floor.map(|f| f.0);
        let x = Axis::fit(all().map(|p| p.0), chart.log_x, 12);
        let y = Axis::fit(all().map(|p| p.1).chain(floor_y), chart.log_y, 10);

        let top = if chart.subtitle.is_empty() { 72 } else { 104 };
        let (width, height) = (SIZE.0 as i32, SIZE.1 as i32);
        // Room on the right: the legend, or the widest line-end label.
        let names = chart.series.iter().map(|s| s.name.as_str());
        let (right_room, legend) = if chart.direct_labels {
            let widest = names.map(|n| width_of(n, END_SIZE)).max().unwrap_or(0);
            ((widest + 2 * PAD + 24).clamp(30, width * 2 / 5), None)
        } else if chart.series.is_empty() && chart.highlight.is_none() {
            (30, None)
        } else {
            let widest = names
                .chain(chart.highlight.map(|h| h.name.as_str()))
                .map(|n| width_of(n, LEGEND_SIZE))
                .max()
                .unwrap_or(0);
            let w = (widest + 96).clamp(190, 440);
            (w + 20, Some(w))
        };
        let plot = PxRect {
            x0: EDGE + Y_TEXT_ROOM,
            y0: top,
            x1: width - EDGE - right_room,
            y1: height - EDGE - X_TEXT_ROOM,
        };
        let legend = legend.map(|w| {
            let rows = chart.series.len() + usize::from(chart.highlight.is_some());
            let max_rows = ((plot.y1 - plot.y0 - 20) / LEGEND_ROW) as usize;
            let rows = rows.min(max_rows.max(1)) as i32;
            PxRect {
                x0: width - EDGE - w,
                y0: plot.y0,
                x1: width - EDGE,
                y1: plot.y0 + 10 + rows * LEGEND_ROW,
            }
        });
        let to_pixels = |s: &Series| -> Vec<Option<(i32, i32)>> {
            s.points
                .iter()
                .map(|&(px, py)| {
                    let (px, py) = (to_plot(px, x.log)?, to_plot(py, y.log)?);
                    Some((x.pixel(px, plot.x0, plot.x1), y.pixel(py, plot.y1, plot.y0)))
                })
                .collect()
        };
        let points: Vec<_> = chart.series.iter().map(to_pixels).collect();
        let highlight = chart.highlight.map(to_pixels).unwrap_or_default();
        let floor = floor_y
            .and_then(|v| to_plot(v, y.log))
            .map(|v| y.pixel(v, plot.y1, plot.y0));

        let mut plan = Plan {
            x,
            y,
            plot,
            points,
            highlight,
            floor,
            labels: Vec::new(),
            legend,
        };
        plan.place_labels(chart);
        plan
    }

    /// Line-end names first (nearest their line's end, top line first),
    /// then the floor's label, then the text beside each point.
    pub(super) fn place_labels(&mut self, chart: &Chart) {
        let plot = self.plot;
        let mut placer = Placer {
            bounds: PxRect {
                x0: plot.x0 + 2,
                y0: plot.y0 + 2,
                x1: plot.x1 - 2,
                y1: plot.y1 - 2,
            },
            taken: Vec::new(),
            markers: Vec::new(),
            lines: Vec::new(),
        };
        for (s, pts) in chart.series.iter().zip(&self.points) {
            let r = s.marker_radius() + 1;
            placer
                .markers
                .extend(pts.iter().flatten().map(|&p| PxRect::around(p, r)));
            for run in runs(pts) {
                placer.lines.extend(samples(&run, 4.0));
            }
        }
        placer.markers.extend(
            self.highlight
                .iter()
                .flatten()
                .map(|&p| PxRect::around(p, FRONT_RING)),
        );
        for run in runs(&self.highlight) {
            placer.lines.extend(samples(&run, 4.0));
        }
        if let Some(fy) = self.floor {
            let mut x = plot.x0;
            while x <= plot.x1 {
                placer.lines.push((x, fy));
                x += 4;
            }
        }
        let line_height = |size: f64| size.round() as i32 + 8;

        if chart.direct_labels {
            let mut ends: Vec<(usize, (i32, i32))> = self
                .points
                .iter()
                .enumerate()
                .filter_map(|(i, pts)| Some((i, *pts.iter().rev().flatten().next()?)))
                .collect();
            // Columns of lines that end at about the same x, right first;
            // in each, the names stacked in the order the lines end, top
            // first, so that leaders do not cross.
            ends.sort_by_key(|&(i, p)| (std::cmp::Reverse(p.0), i));
            let inner = placer.bounds;
            // Names may reach into the room right of the plot.
            placer.bounds.x1 = SIZE.0 as i32 - EDGE;
            let h = line_height(END_SIZE);
            while let Some(&(_, (right, _))) = ends.first() {
                let split = ends.iter().position(|&(_, p)| right - p.0 > 24);
                let rest = ends.split_off(split.unwrap_or(ends.len()));
                let mut column = std::mem::replace(&mut ends, rest);
                column.sort_by_key(|&(i, p)| (p.1, i));
                let x0 = column
                    .iter()
                    .map(|&(i, p)| p.0 + chart.series[i].marker_radius())
                    .max()
                    .unwrap_or(0)
                    + 8;
                let wishes: Vec<i32> = column.iter().map(|&(_, p)| p.1).collect();
                let ys = stack(&wishes, h, inner.y0, inner.y1);
                for (&(i, end), cy) in column.iter().zip(ys) {
                    let s = &chart.series[i];
                    let w = width_of(&s.name, END_SIZE) + 2 * PAD;
                    let mut spots = vec![PxRect::left_centre(x0, cy, w, h)];
                    spots.extend(beside_end(x0, end.1, w, h, inner.y0, inner.y1));
                    let Some(rect) = placer.place(&spots) else {
                        continue;
                    };
                    let moved = (rect.centre_y() - end.1).abs() > h / 3
                        || rect.x0 - end.0 > s.marker_radius() + 14;
                    self.labels.push(Placed {
                        kind: LabelKind::End,
                        text: s.name.clone(),
                        size: END_SIZE,
                        rect,
                        colour: text_colour(s.colour_at(i)),
                        leader: moved.then_some((end, (rect.x0, rect.centre_y()))),
                    });
                }
            }
            placer.bounds = inner;
        }

        if let (Some((_, full)), Some(fy)) = (chart.floor, self.floor) {
            let h = line_height(POINT_SIZE);
            // Just above the line at the left, else just below, else anywhere
            // along it; where the whole text fits nowhere, its first words
            // ("noise floor (…)"), and where those do not either, above the
            // line at the left all the same: the floor is always named.
            let spots_for = |text: &str| {
                let w = width_of(text, POINT_SIZE) + 2 * PAD;
                let mut spots = Vec::new();
                let mut x0 = plot.x0 + 8;
                while x0 + w < plot.x1 {
                    spots.push(PxRect {
                        x0,
                        y0: fy - h - 1,
                        x1: x0 + w,
                        y1: fy - 1,
                    });
                    spots.push(PxRect {
                        x0,
                        y0: fy + 2,
                        x1: x0 + w,
                        y1: fy + 2 + h,
                    });
                    x0 += 12;
                }
                spots
            };
            let short = full.split(':').next().unwrap_or(full);
            let placed = placer
                .place(&spots_for(full))
                .map(|rect| (full, rect))
                .or_else(|| placer.place(&spots_for(short)).map(|rect| (short, rect)))
                .or_else(|| {
                    let rect = *spots_for(short).first()?;
                    placer.taken.push(rect);
                    Some((short, rect))
                });
            if let Some((text, rect)) = placed {
                self.labels.push(Placed {
                    kind: LabelKind::Floor,
                    text: text.to_owned(),
                    size: POINT_SIZE,
                    rect,
                    colour: FLOOR_COLOUR,
                    leader: None,
                });
            }
        }

        for (i, (s, pts)) in chart.series.iter().zip(&self.points).enumerate() {
            for (p, text) in pts.iter().zip(&s.point_labels) {
                let (Some(p), false) = (p, text.is_empty()) else {
                    continue;
                };
                let repeated = self.labels.iter().any(|l| {
                    l.kind == LabelKind::Point
                        && l.text == *text
                        && l.leader
                            .is_some_and(|(a, _)| (a.0 - p.0).abs() <= 12 && (a.1 - p.1).abs() <= 6)
                });
                if repeated {
                    continue;
                }
                let w = width_of(text, POINT_SIZE) + 2 * PAD;
                let h = line_height(POINT_SIZE) - 4;
                let spots = around_point(*p, s.marker_radius(), w, h, 3);
                let Some(rect) = placer.place_near(&spots) else {
                    continue;
                };
                self.labels.push(Placed {
                    kind: LabelKind::Point,
                    text: text.clone(),
                    size: POINT_SIZE,
                    rect,
                    colour: text_colour(s.colour_at(i)),
                    // Where the label belongs; drawn only if it is far.
                    leader: Some((*p, nearest_on(&rect, *p))),
                });
            }
        }
    }
}

/// The point of `r`'s outline nearest `p`.
pub(super) fn nearest_on(r: &PxRect, p: (i32, i32)) -> (i32, i32) {
    (p.0.clamp(r.x0, r.x1), p.1.clamp(r.y0, r.y1))
}

/// How far a point label may sit from its point before a leader is drawn.
pub(super) const LEADER_FROM: i32 = 16;
