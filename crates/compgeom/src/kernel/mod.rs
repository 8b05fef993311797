//! The geometry kernel: basic types and exact predicates.
//!
//! The kernel knows nothing about algorithms; every algorithm module builds on it.
//!
//! ## What is exact
//!
//! | operation | exact? |
//! |---|---|
//! | [`orient2d`], [`incircle`], [`orient3d`], [`insphere`] on input points | yes, for every finite `f64` input (filtered; exact fallback) |
//! | [`compare_xy`] and coordinate comparisons | yes (they only compare values) |
//! | comparisons involving a [`Crossing`] (a constructed segment crossing) | yes (decided from the defining segments) |
//! | [`Crossing::approx`] | rounded: the nearest `f64` point, used only for reporting |
mod crossing;
mod predicates;
mod types;

pub use crossing::Crossing;
pub use predicates::{
    compare_xy, compare_xyz, incircle, insphere, orient2d, orient3d, CircleSide, Orientation,
    PlaneSide, SphereSide,
};
pub use types::{
    ensure_finite, Bbox2, Line2, MultiPolygon, Point2, Point3, Polygon, Segment2, Vector2, Vector3,
};
