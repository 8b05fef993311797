//! Pictures: an SVG writer that draws points, segments, polylines, polygons with holes and
//! text labels in named, styled layers, with a legend and a title, scaled to fit; and an HTML
//! [`Gallery`] that collects pictures with their figures (sizes, times).
//!
//! Pictures are how people check geometry, so the writer favours clarity over features:
//!
//! - Data coordinates are mathematical (y up). [`Picture::to_svg_string`] computes the
//!   bounding box of everything drawn, scales it uniformly (aspect ratio kept) to fit the
//!   requested pixel size inside a margin, and flips y.
//! - Stroke widths, point radii and font sizes are in screen pixels: coordinates are
//!   transformed into screen space here, so a thin line stays thin however small the data.
//! - Degenerate extents are ordinary: an empty picture, a single point, or points all on one
//!   horizontal or vertical line are centred, and the output never contains `NaN` or `inf`.
//!   Marks with a non-finite coordinate are skipped (they cannot be placed).
//! - Huge coordinates (up to `f64::MAX`) do not overflow: widths are computed from halves.
//! - All text (title, legend names, labels) is escaped for XML.
//!
//! Cost: O(number of marks) time and output size.
//!
//! ```
//! use compgeom::render::{Layer, Picture, Style};
//! use compgeom::Point2;
//!
//! let pts = [Point2::new(0.0, 0.0), Point2::new(4.0, 0.0), Point2::new(0.0, 3.0)];
//! let mut pic = Picture::new(400, 300).with_title("three points");
//! pic.add(Layer::new("input", Style::points("#333")).numbered_points(&pts));
//! let svg = pic.to_svg_string();
//! assert!(svg.starts_with("<svg"));
//! assert!(svg.contains("three points"));
//! assert!(!svg.contains("NaN"));
//! ```

mod gallery;
mod picture;
mod style;
mod xml;

pub use gallery::{Figure, FigureImage, Gallery, Section};
pub use picture::{Layer, Mark, Picture};
pub use style::Style;
pub use xml::escape as escape_xml;
