//! The geometry kernel: basic types and exact predicates.
//!
//! The kernel knows nothing about algorithms; every algorithm module builds on it.
//!
//! ## What is exact
//!
//! | operation | exact? | how |
//! |---|---|---|
//! | [`orient2d`], [`incircle`], [`orient3d`], [`insphere`] on input points | yes, for every finite `f64` input | for `orient2d` a plain `f64` evaluation with Shewchuk's error bound first; `robust` (Shewchuk) inside a per-predicate safe exponent range, exact power-of-two scaling into it, else exact dyadic arithmetic |
//! | [`compare_xy`], [`compare_xyz`] and coordinate comparisons | yes | they only compare values |
//! | [`Crossing::new`] (are the lines parallel?), [`compare_slopes`] | yes | floating-point filter, exact fallback |
//! | [`Crossing::compare_xy_point`], [`Crossing::compare_xy`], [`Crossing::orient`], [`ExactPoint::compare_xy`], [`ExactPoint::compare_x`], [`orient_exact`], [`compare_y_at_x`], [`on_segment`] | yes, for every finite input | floating-point filter, exact dyadic fallback (decided from the defining segments) |
//! | [`segment_intersection`] | yes: the kind of intersection is exact; a shared endpoint is reported as that input point, never recomputed | exact predicates |
//! | [`ring_area2_exact`], [`Polygon::area2_exact`], [`MultiPolygon::area2_exact`] | yes | exact dyadic sums |
//! | [`ring_area`], [`Polygon::area`], [`MultiPolygon::area`] | no: `f64` shoelace sums | each ring relative to its first vertex |
//! | [`Crossing::approx`], [`ExactPoint::approx`] | rounded: the nearest `f64` per coordinate (correctly rounded, ties to even); `±inf` if the exact coordinate is beyond the `f64` range | double-double midpoint filter, exact rational rounding fallback |
//!
//! Non-finite coordinates are rejected by the algorithms ([`ensure_finite`]) before any
//! predicate runs; the predicates themselves never panic on them and return a
//! documented degenerate answer.
mod area;
pub(crate) mod arith;
mod crossing;
pub(crate) mod exact;
pub(crate) mod filter;
mod intersection;
mod predicates;
pub(crate) mod steps;
mod types;

pub(crate) use area::ring_area_scaled;
pub use area::{ring_area, ring_area2_exact};
pub use crossing::{
    compare_slopes, compare_y_at_x, on_segment, orient_exact, Crossing, ExactPoint,
};
#[doc(hidden)]
pub use filter::{crossing_fallbacks, predicate_fallbacks};
pub(crate) use intersection::{orient_static, quick_crossing_static, static_orient_bound};
pub use intersection::{segment_intersection, SegmentIntersection};
pub use predicates::{
    compare_xy, compare_xyz, incircle, insphere, orient2d, orient3d, CircleSide, Orientation,
    PlaneSide, SphereSide,
};
pub use types::{
    ensure_finite, Bbox2, Line2, MultiPolygon, Point2, Point3, Polygon, Segment2, Vector2, Vector3,
};
