//! Red/blue segment intersection (the map-overlay case of book §2.3): two sets of
//! segments, each without crossings inside itself (like the edges of two planar
//! subdivisions), and only the intersections between a red and a blue segment wanted.
//!
//! One sweep over both sets. Same-colour segments may meet only at points that are
//! endpoints of both, so there are O(n) same-colour contact points and the time stays
//! O((n + I) log n) for I red–blue intersection points. If two segments of one set cross,
//! touch in an interior point or overlap, the input breaks that promise and the answer is
//! an [`Error::InvalidInput`] naming the two segments and the point.

use super::sweep::{sweep, Flow, Sink};
use super::{sort_overlaps, IntersectionPoint, Overlap};
use crate::kernel::{ExactPoint, Point2, Segment2};
use crate::{Error, Result};

/// A point where red and blue segments meet.
#[derive(Debug, Clone, PartialEq)]
pub struct RedBluePoint {
    /// The nearest `f64` point.
    pub point: Point2,
    /// The exact point.
    pub exact: ExactPoint,
    /// The red segments through it (indices into the red slice), ascending.
    pub red: Vec<usize>,
    /// The blue segments through it (indices into the blue slice), ascending.
    pub blue: Vec<usize>,
}

/// A maximal piece along which the same red and blue segments overlap.
#[derive(Debug, Clone, PartialEq)]
pub struct RedBlueOverlap {
    /// The red segment(s) covering the piece.
    pub red: Vec<usize>,
    /// The blue segment(s) covering the piece.
    pub blue: Vec<usize>,
    /// The end met first in sweep order.
    pub from: Point2,
    /// The other end.
    pub to: Point2,
}

/// The red–blue intersections, in sweep order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RedBlueIntersections {
    /// Points where at least one red and one blue segment meet, in sweep order.
    pub points: Vec<RedBluePoint>,
    /// Red–blue overlaps, ordered by `from`, then `to`.
    pub overlaps: Vec<RedBlueOverlap>,
}

struct RedBlue<'a> {
    /// Red then blue: what the sweep numbers.
    segments: &'a [Segment2],
    reds: usize,
    out: RedBlueIntersections,
    overlaps: Vec<Overlap>,
    error: Option<Error>,
}

impl RedBlue<'_> {
    fn colour(&self, i: usize) -> (&'static str, usize) {
        if i < self.reds {
            ("red", i)
        } else {
            ("blue", i - self.reds)
        }
    }

    /// A same-colour contact that is not at a common endpoint, if any.
    fn same_colour_violation(&self, p: &IntersectionPoint) -> Option<Error> {
        for &c in p.interior() {
            let red = c < self.reds;
            if let Some(&o) = p
                .segments()
                .iter()
                .find(|&&o| o != c && (o < self.reds) == red)
            {
                let ((name, a), (_, b)) = (self.colour(c.min(o)), self.colour(c.max(o)));
                return Some(Error::InvalidInput(format!(
                    "{name} segments {a} and {b} meet at ({}, {}), which is not an endpoint of both; \
                     segments of one set may meet only at common endpoints",
                    p.point.x, p.point.y
                )));
            }
        }
        None
    }
}

impl Sink for RedBlue<'_> {
    fn point(&mut self, p: IntersectionPoint) -> Flow {
        if let Some(e) = self.same_colour_violation(&p) {
            self.error = Some(e);
            return Flow::Stop;
        }
        let (red, blue): (Vec<usize>, Vec<usize>) =
            p.segments().iter().partition(|&&i| i < self.reds);
        if !red.is_empty() && !blue.is_empty() {
            self.out.points.push(RedBluePoint {
                point: p.point,
                exact: p.exact(self.segments),
                red,
                blue: blue.iter().map(|b| b - self.reds).collect(),
            });
        }
        Flow::Continue
    }

    fn overlap(&mut self, o: Overlap) -> Flow {
        let reds = o.segments.iter().filter(|&&i| i < self.reds).count();
        let blues = o.segments.len() - reds;
        if reds >= 2 || blues >= 2 {
            // Segments are sorted, reds first: two of one colour are adjacent.
            let k = if reds >= 2 { 0 } else { reds };
            let ((name, a), (_, b)) = (self.colour(o.segments[k]), self.colour(o.segments[k + 1]));
            self.error = Some(Error::InvalidInput(format!(
                "{name} segments {a} and {b} overlap from ({}, {}) to ({}, {}); \
                 segments of one set may meet only at common endpoints",
                o.from.x, o.from.y, o.to.x, o.to.y
            )));
            return Flow::Stop;
        }
        self.overlaps.push(o);
        Flow::Continue
    }
}

/// The intersections between a red and a blue segment (closed segments; meaning as in
/// [`super::find_intersections`]), when neither set has crossings within itself.
///
/// Errors: a non-finite coordinate ("segment i" numbers red first, then blue); two
/// segments of one set that cross, touch in an interior point or overlap.
///
/// ```
/// use compgeom::intersect::red_blue_intersections;
/// use compgeom::{Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// let red = [s((0.0, 0.0), (2.0, 2.0)), s((2.0, 2.0), (4.0, 0.0))]; // meet at an endpoint
/// let blue = [s((0.0, 1.0), (4.0, 1.0))];
/// let found = red_blue_intersections(&red, &blue).unwrap();
/// assert_eq!(found.points.len(), 2);
/// assert_eq!(found.points[0].point, Point2::new(1.0, 1.0));
/// assert_eq!((found.points[1].red.clone(), found.points[1].blue.clone()), (vec![1], vec![0]));
/// ```
pub fn red_blue_intersections(red: &[Segment2], blue: &[Segment2]) -> Result<RedBlueIntersections> {
    let all: Vec<Segment2> = red.iter().chain(blue).copied().collect();
    let mut sink = RedBlue {
        segments: &all,
        reds: red.len(),
        out: RedBlueIntersections::default(),
        overlaps: Vec::new(),
        error: None,
    };
    sweep(&all, &mut sink)?;
    if let Some(e) = sink.error {
        return Err(e);
    }
    let mut overlaps = sink.overlaps;
    sort_overlaps(&mut overlaps);
    sink.out.overlaps = overlaps
        .into_iter()
        .map(|o| RedBlueOverlap {
            red: o
                .segments
                .iter()
                .copied()
                .filter(|&i| i < red.len())
                .collect(),
            blue: o
                .segments
                .iter()
                .filter(|&&i| i >= red.len())
                .map(|i| i - red.len())
                .collect(),
            from: o.from,
            to: o.to,
        })
        .collect();
    Ok(sink.out)
}
