//! Loose quadtree, rebuilt every step: for radii that differ by orders of
//! magnitude.
//!
//! A grid must size its cells for the largest disc; a tree sizes each node
//! for the discs it holds. Building splits a node's discs at the middle of
//! their centres into four quadrants. A disc goes down into its quadrant only
//! if its radius is at most half the quadrant's extent, so it sticks out of
//! the quadrant by at most that much on each side and a child's bounding box
//! is at most twice its quadrant ("loose" by a factor of 2). Larger discs stay
//! in the node. Small discs thus sink to small nodes and large discs stay
//! high, whatever the mix: a 10³ m disc among 10⁻⁴ m ones costs one node.
//!
//! The discs are stored in tree order (a node's own discs, then its
//! children's), and every node keeps the bounding box of all discs below it
//! and of its own discs. The pairs are then found node by node: a node's own
//! discs are tested among themselves, and the node's own box queries the
//! tree for the nodes stored after it whose boxes it touches, whose own
//! discs are tested against the node's. So each pair is met once, and one
//! traversal serves all of a leaf's discs. The pairs are put in `(i, j)`
//! order by a counting sort.
//!
//! Cost: building is O(n·depth): each split is a counting sort of the
//! node's discs into five groups (own, four quadrants) that also measures
//! the children's boxes; a query visits O(depth + nearby nodes). For n discs
//! of similar size that is O(n log n) per step, several times a grid's cost
//! (about 100–200 ns per disc for n = 10³–10⁵); for mixed radii it stays
//! close to that while the grid's cells grow with the largest disc.
//!
//! Splits stop at `LEAF` (8) discs, at depth `MAX_DEPTH` (48), or when the
//! centres coincide, so coincident discs, far-away discs and any finite
//! input end in bounded time (a far-away disc is split off in one step,
//! since splits follow the discs' own extent, not a fixed root square).
//!
//! - **Periodic**: centres are wrapped into the box, and a node whose query
//!   box, shifted by ± the box size, still touches the tree queries those
//!   images too (the minimum image decides; duplicates are removed).
//! - **Box and open**: no special case.

use super::{pair, sort_pairs, touches, BroadPhase, BruteForce, Disc, Pair, Space};
use crate::boundary::Boundary;
use crate::particle::Particle;
use glam::DVec2;

/// A node with at most this many discs is not split.
const LEAF: usize = 8;
/// Nodes at this depth are not split.
const MAX_DEPTH: u32 = 48;

/// An axis-aligned box: min x, min y, max x, max y.
type Aabb = [f64; 4];

/// The box that touches nothing.
const EMPTY: Aabb = [
    f64::INFINITY,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NEG_INFINITY,
];

/// Loose quadtree broad phase: for mixed radii.
#[derive(Clone, Debug, Default)]
pub struct Quadtree {
    /// The candidate discs, in tree order after building.
    items: Vec<Disc>,
    /// Scratch for splitting a node's discs.
    scratch: Vec<Disc>,
    /// The tree; node 0 is the root.
    nodes: Vec<Node>,
    /// Scratch: nodes still to build.
    work: Vec<Task>,
    /// Scratch: nodes still to visit in a query.
    stack: Vec<u32>,
    /// Pairs as found, before sorting.
    raw: Vec<Pair>,
    /// Scratch for the pair sort.
    ends: Vec<u32>,
}

/// A node: its discs are `items[start..own_end]`, its subtree's
/// `items[start..end]`, its children `nodes[first_child..][..children]`.
#[derive(Clone, Copy, Debug)]
struct Node {
    /// Bounding box of every disc in the subtree.
    bbox: Aabb,
    /// Bounding box of the node's own discs.
    own_bbox: Aabb,
    start: u32,
    own_end: u32,
    end: u32,
    first_child: u32,
    children: u32,
}

impl Default for Node {
    fn default() -> Self {
        Node {
            bbox: EMPTY,
            own_bbox: EMPTY,
            start: 0,
            own_end: 0,
            end: 0,
            first_child: 0,
            children: 0,
        }
    }
}

/// A node to build from `items[start..end]`, whose boxes are `bounds`.
#[derive(Clone, Copy, Debug)]
struct Task {
    node: u32,
    start: u32,
    end: u32,
    depth: u32,
    bounds: Bounds,
}

impl BroadPhase for Quadtree {
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        out.clear();
        self.raw.clear();
        let Some(mut space) = Space::new(boundary, size) else {
            BruteForce.candidate_pairs(particles, boundary, size, out);
            return;
        };
        self.items.clear();
        let mut r_max = 0.0f64;
        let mut bounds = Bounds::EMPTY;
        for (i, p) in particles.iter().enumerate() {
            if let Some(d) = space.disc(i, p) {
                if d.r.is_finite() {
                    r_max = r_max.max(d.r.abs());
                }
                bounds.add(&d);
                self.items.push(d);
            }
        }
        space.finish();
        if self.items.len() < 2 {
            return;
        }
        self.build(bounds);
        if space.period.is_some() {
            self.query::<true>(&space, r_max);
        } else {
            self.query::<false>(&space, r_max);
        }
        sort_pairs(&self.raw, particles.len(), &mut self.ends, out);
    }
}

impl Quadtree {
    /// Builds the tree over `items` (whose boxes are `bounds`), reordering
    /// them. Each split is a counting sort into five groups (own discs and
    /// four quadrants) through `scratch`, which also measures the groups'
    /// boxes for the children.
    fn build(&mut self, bounds: Bounds) {
        self.nodes.clear();
        self.nodes.push(Node::default());
        self.scratch.resize(self.items.len(), Disc::default());
        self.work.clear();
        self.work.push(Task {
            node: 0,
            start: 0,
            end: self.items.len() as u32,
            depth: 0,
            bounds,
        });
        while let Some(task) = self.work.pop() {
            let (start, end) = (task.start as usize, task.end as usize);
            let Bounds {
                aabb: bbox,
                centres: [cx0, cy0, cx1, cy1],
            } = task.bounds;
            // Halves of the centre box, written so they cannot overflow.
            let half = (0.5 * cx1 - 0.5 * cx0).max(0.5 * cy1 - 0.5 * cy0);
            let mid = DVec2::new(0.5 * cx0 + 0.5 * cx1, 0.5 * cy0 + 0.5 * cy1);
            let node = &mut self.nodes[task.node as usize];
            node.bbox = bbox;
            node.start = task.start;
            node.end = task.end;
            node.own_end = task.end;
            node.own_bbox = bbox;
            // Coincident centres (or no extent at all) cannot be split.
            let spread = half > 0.0;
            if end - start <= LEAF || task.depth >= MAX_DEPTH || !spread {
                continue;
            }
            // Group 0: discs too large for a quadrant (of extent `half`),
            // which stay here; groups 1–4: the quadrants.
            let items = &mut self.items[start..end];
            let mut counts = [0usize; 5];
            for d in items.iter_mut() {
                let group = if d.r > 0.5 * half {
                    0
                } else {
                    1 + 2 * usize::from(d.x >= mid.x) + usize::from(d.y >= mid.y)
                };
                d.tag = group as u32;
                counts[group] += 1;
            }
            if counts[0] == 0 && counts.contains(&(end - start)) {
                continue; // no progress (rounding at the midpoint): a leaf
            }
            let mut cursor = [0usize; 5];
            for g in 1..5 {
                cursor[g] = cursor[g - 1] + counts[g - 1];
            }
            let firsts = cursor;
            let mut groups = [Bounds::EMPTY; 5];
            let scratch = &mut self.scratch[..end - start];
            for d in items.iter() {
                let g = d.tag as usize;
                scratch[cursor[g]] = *d;
                cursor[g] += 1;
                groups[g].add(d);
            }
            items.copy_from_slice(scratch);
            let first_child = self.nodes.len() as u32;
            let mut children = 0;
            for g in (1..5).filter(|&g| counts[g] > 0) {
                self.work.push(Task {
                    node: first_child + children,
                    start: (start + firsts[g]) as u32,
                    end: (start + firsts[g] + counts[g]) as u32,
                    depth: task.depth + 1,
                    bounds: groups[g],
                });
                children += 1;
            }
            self.nodes
                .extend(std::iter::repeat_n(Node::default(), children as usize));
            let node = &mut self.nodes[task.node as usize];
            node.own_end = (start + counts[0]) as u32;
            node.own_bbox = groups[0].aabb;
            node.first_child = first_child;
            node.children = children;
        }
    }

    /// Finds the pairs node by node: a node's own discs are tested among
    /// themselves, then against the own discs of every later node (in tree
    /// order) whose box touches theirs. One traversal serves all of a
    /// node's discs.
    fn query<const PERIODIC: bool>(&mut self, space: &Space, r_max: f64) {
        let (items, nodes, stack, raw) = (&self.items, &self.nodes, &mut self.stack, &mut self.raw);
        let root = nodes[0].bbox;
        let shifts: &[f64] = if PERIODIC { &[0.0, -1.0, 1.0] } else { &[0.0] };
        let period = space.period.unwrap_or(DVec2::ZERO);
        for node in nodes {
            let (first, own_end) = (node.start as usize, node.own_end as usize);
            let own = &items[first..own_end];
            for (k, a) in own.iter().enumerate() {
                for b in &own[k + 1..] {
                    if touches::<PERIODIC>(a, b, space) {
                        raw.push(pair(a.i, b.i));
                    }
                }
            }
            if own.is_empty() || node.end as usize == own_end && own_end == items.len() {
                continue;
            }
            // Widen the box by the rounding of the discs' interval ends.
            let [x0, y0, x1, y1] = node.own_bbox;
            let scale = x0.abs().max(y0.abs()).max(x1.abs()).max(y1.abs());
            let slack = space.slack + 8.0 * f64::EPSILON * (scale + r_max);
            let first_found = raw.len();
            let mut images = 0;
            for &kx in shifts {
                for &ky in shifts {
                    let (sx, sy) = (kx * period.x, ky * period.y);
                    let q = [
                        x0 + sx - slack,
                        y0 + sy - slack,
                        x1 + sx + slack,
                        y1 + sy + slack,
                    ];
                    if !touch(&root, &q) {
                        continue;
                    }
                    images += 1;
                    stack.clear();
                    stack.push(0);
                    while let Some(m) = stack.pop() {
                        let other = &nodes[m as usize];
                        // Only discs stored after this node's own ones.
                        if other.end as usize <= own_end || !touch(&other.bbox, &q) {
                            continue;
                        }
                        if other.start as usize >= own_end && touch(&other.own_bbox, &q) {
                            for b in &items[other.start as usize..other.own_end as usize] {
                                for a in own {
                                    if touches::<PERIODIC>(a, b, space) {
                                        raw.push(pair(a.i, b.i));
                                    }
                                }
                            }
                        }
                        stack.extend(other.first_child..other.first_child + other.children);
                    }
                }
            }
            if images > 1 {
                // A small box may be reached through two images.
                let found = &mut raw[first_found..];
                found.sort_unstable();
                let mut kept = 0;
                for k in 0..found.len() {
                    if kept == 0 || found[k] != found[kept - 1] {
                        found[kept] = found[k];
                        kept += 1;
                    }
                }
                raw.truncate(first_found + kept);
            }
        }
    }
}

/// The boxes of a group of discs: of the discs and of their centres.
#[derive(Clone, Copy, Debug)]
struct Bounds {
    aabb: Aabb,
    centres: Aabb,
}

impl Bounds {
    const EMPTY: Bounds = Bounds {
        aabb: EMPTY,
        centres: EMPTY,
    };

    /// Grows the boxes to take in `d` (for a negative radius, its inverted
    /// box, whose hull still touches every box that touches it).
    #[inline(always)]
    fn add(&mut self, d: &Disc) {
        grow(&mut self.aabb, d.x - d.r, d.y - d.r, d.x + d.r, d.y + d.r);
        grow(&mut self.centres, d.x, d.y, d.x, d.y);
    }
}

/// Grows a box. Plain selects (one `minsd`/`maxsd` each): nothing here is
/// NaN, and `f64::min` pays for handling it.
#[inline(always)]
fn grow(b: &mut Aabb, x0: f64, y0: f64, x1: f64, y1: f64) {
    b[0] = if x0 < b[0] { x0 } else { b[0] };
    b[1] = if y0 < b[1] { y0 } else { b[1] };
    b[2] = if x1 > b[2] { x1 } else { b[2] };
    b[3] = if y1 > b[3] { y1 } else { b[3] };
}

/// Whether two boxes touch (closed intervals on both axes).
#[inline(always)]
fn touch(a: &Aabb, b: &Aabb) -> bool {
    // `&`, not `&&`: four cheap comparisons beat a mispredicted branch.
    (a[0] <= b[2]) & (b[0] <= a[2]) & (a[1] <= b[3]) & (b[1] <= a[3])
}
