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
//! Every node keeps the bounding box of all discs below it and of its own
//! discs. Each disc then queries the tree with its own bounding box, visiting
//! only nodes whose box it touches and only discs stored after it (each pair
//! is found once). The pairs are put in `(i, j)` order by a counting sort.
//!
//! Cost: building is O(n·depth) (an in-place partition per level, like
//! quicksort); each query visits O(depth + nearby nodes). For n discs of
//! similar size that is O(n log n) per step, a few times a grid's cost; for
//! mixed radii it stays close to that while the grid's cells grow with the
//! largest disc.
//!
//! Splits stop at [`LEAF`] discs, at depth [`MAX_DEPTH`], or when the centres
//! coincide, so coincident discs, far-away discs and any finite input end in
//! bounded time (the centre box of a far-away disc is split off in one step,
//! since splits follow the discs' own extent, not a fixed root square).
//!
//! - **Periodic**: centres are wrapped into the box, and a disc whose query
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

/// A node to build from `items[start..end]`.
#[derive(Clone, Copy, Debug)]
struct Task {
    node: u32,
    start: u32,
    end: u32,
    depth: u32,
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
        for (i, p) in particles.iter().enumerate() {
            if let Some(d) = space.disc(i, p) {
                if d.r.is_finite() {
                    r_max = r_max.max(d.r.abs());
                }
                self.items.push(d);
            }
        }
        space.finish();
        if self.items.len() < 2 {
            return;
        }
        self.build();
        if space.period.is_some() {
            self.query::<true>(&space, r_max);
        } else {
            self.query::<false>(&space, r_max);
        }
        sort_pairs(&self.raw, particles.len(), &mut self.ends, out);
    }
}

impl Quadtree {
    /// Builds the tree over `items`, reordering them.
    fn build(&mut self) {
        self.nodes.clear();
        self.nodes.push(Node::default());
        self.work.clear();
        self.work.push(Task {
            node: 0,
            start: 0,
            end: self.items.len() as u32,
            depth: 0,
        });
        while let Some(task) = self.work.pop() {
            let (start, end) = (task.start as usize, task.end as usize);
            let items = &mut self.items[start..end];
            let bbox = aabb(items);
            let (mut c_lo, mut c_hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
            for d in items.iter() {
                let c = DVec2::new(d.x, d.y);
                c_lo = c_lo.min(c);
                c_hi = c_hi.max(c);
            }
            // Halves of the centre box, written so they cannot overflow.
            let half = (0.5 * c_hi - 0.5 * c_lo).max_element();
            let mid = 0.5 * c_lo + 0.5 * c_hi;
            let node = &mut self.nodes[task.node as usize];
            node.bbox = bbox;
            node.start = task.start;
            node.end = task.end;
            node.own_end = task.end;
            node.own_bbox = bbox;
            if items.len() <= LEAF || task.depth >= MAX_DEPTH || !(half > 0.0) {
                continue;
            }
            // Discs too large for a quadrant (of extent `half`) stay here.
            let own = partition(items, |d| d.r > 0.5 * half);
            let rest = &mut items[own..];
            let left = partition(rest, |d| d.x < mid.x);
            let (l, r) = rest.split_at_mut(left);
            let (low_left, low_right) =
                (partition(l, |d| d.y < mid.y), partition(r, |d| d.y < mid.y));
            let cuts = [
                start + own,
                start + own + low_left,
                start + own + left,
                start + own + left + low_right,
                end,
            ];
            if own == 0 && cuts.windows(2).any(|w| w[1] - w[0] == end - start) {
                continue; // no progress (rounding at the midpoint): a leaf
            }
            let own_bbox = aabb(&self.items[start..start + own]);
            let first_child = self.nodes.len() as u32;
            let mut children = 0;
            for w in cuts.windows(2).filter(|w| w[1] > w[0]) {
                self.work.push(Task {
                    node: first_child + children,
                    start: w[0] as u32,
                    end: w[1] as u32,
                    depth: task.depth + 1,
                });
                children += 1;
            }
            self.nodes
                .extend(std::iter::repeat_n(Node::default(), children as usize));
            let node = &mut self.nodes[task.node as usize];
            node.own_end = (start + own) as u32;
            node.own_bbox = own_bbox;
            node.first_child = first_child;
            node.children = children;
        }
    }

    /// Queries every disc against the discs stored after it.
    fn query<const PERIODIC: bool>(&mut self, space: &Space, r_max: f64) {
        let (items, nodes, stack, raw) = (&self.items, &self.nodes, &mut self.stack, &mut self.raw);
        let root = nodes[0].bbox;
        let shifts: &[f64] = if PERIODIC { &[0.0, -1.0, 1.0] } else { &[0.0] };
        let period = space.period.unwrap_or(DVec2::ZERO);
        for (pa, a) in items.iter().enumerate() {
            let slack =
                space.slack + 8.0 * f64::EPSILON * (a.x.abs().max(a.y.abs()) + a.r.abs() + r_max);
            let reach = a.r + slack;
            let first = raw.len();
            let mut images = 0;
            for &kx in shifts {
                for &ky in shifts {
                    let (x, y) = (a.x + kx * period.x, a.y + ky * period.y);
                    let q = [x - reach, y - reach, x + reach, y + reach];
                    if !touch(&root, &q) {
                        continue;
                    }
                    images += 1;
                    stack.clear();
                    stack.push(0);
                    while let Some(k) = stack.pop() {
                        let node = &nodes[k as usize];
                        if node.end as usize <= pa + 1 || !touch(&node.bbox, &q) {
                            continue;
                        }
                        let from = (node.start as usize).max(pa + 1);
                        let own_end = node.own_end as usize;
                        if from < own_end && touch(&node.own_bbox, &q) {
                            for b in &items[from..own_end] {
                                if touches::<PERIODIC>(a, b, space) {
                                    raw.push(pair(a.i, b.i));
                                }
                            }
                        }
                        stack.extend(node.first_child..node.first_child + node.children);
                    }
                }
            }
            if images > 1 {
                // A small box may be reached through two images.
                let found = &mut raw[first..];
                found.sort_unstable();
                let mut kept = 0;
                for k in 0..found.len() {
                    if kept == 0 || found[k] != found[kept - 1] {
                        found[kept] = found[k];
                        kept += 1;
                    }
                }
                raw.truncate(first + kept);
            }
        }
    }
}

/// Moves the discs for which `keep` holds to the front; returns how many.
fn partition(items: &mut [Disc], keep: impl Fn(&Disc) -> bool) -> usize {
    let mut k = 0;
    for m in 0..items.len() {
        if keep(&items[m]) {
            items.swap(k, m);
            k += 1;
        }
    }
    k
}

/// The bounding box of the discs (for negative radii, the inverted boxes'
/// hull, which still touches every box that touches one of them).
fn aabb(items: &[Disc]) -> Aabb {
    let mut b = EMPTY;
    for d in items {
        b[0] = b[0].min(d.x - d.r);
        b[1] = b[1].min(d.y - d.r);
        b[2] = b[2].max(d.x + d.r);
        b[3] = b[3].max(d.y + d.r);
    }
    b
}

/// Whether two boxes touch (closed intervals on both axes).
#[inline(always)]
fn touch(a: &Aabb, b: &Aabb) -> bool {
    a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
}
