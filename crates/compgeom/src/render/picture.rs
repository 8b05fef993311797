//! [`Picture`]: layers of marks, drawn to SVG in screen space.

use super::style::{length, unit, Style};
use super::xml::{escape, num};
use crate::kernel::{Bbox2, Point2, Polygon, Segment2};
use std::fmt::Write as _;

/// One thing drawn in a layer, in data coordinates (y up).
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A dot, optionally labelled (e.g. with its index).
    Point {
        /// Where.
        at: Point2,
        /// Text drawn beside the dot.
        label: Option<String>,
    },
    /// A straight segment.
    Segment(Segment2),
    /// An open polyline.
    Polyline(Vec<Point2>),
    /// A polygon with holes, filled with the even-odd rule (holes are left empty whatever
    /// their orientation).
    Polygon(Polygon),
    /// Free text anchored at a point (left end of its baseline).
    Text {
        /// Anchor.
        at: Point2,
        /// The text (escaped when written).
        text: String,
    },
}

impl Mark {
    /// Every coordinate of the mark.
    fn points(&self) -> Box<dyn Iterator<Item = Point2> + '_> {
        match self {
            Mark::Point { at, .. } | Mark::Text { at, .. } => Box::new(std::iter::once(*at)),
            Mark::Segment(s) => Box::new([s.a, s.b].into_iter()),
            Mark::Polyline(v) => Box::new(v.iter().copied()),
            Mark::Polygon(p) => Box::new(p.rings().flat_map(|r| r.iter().copied())),
        }
    }

    /// True when every coordinate is finite (only such marks are drawn).
    fn is_drawable(&self) -> bool {
        self.points().all(|p| p.is_finite())
    }
}

/// A named, styled group of marks. The name is the legend entry (an empty name leaves the
/// layer out of the legend).
#[derive(Debug, Clone, PartialEq)]
pub struct Layer {
    /// Legend entry.
    pub name: String,
    /// How the marks are drawn.
    pub style: Style,
    /// What is drawn, in order (later marks on top).
    pub marks: Vec<Mark>,
}

impl Layer {
    /// An empty layer.
    pub fn new(name: impl Into<String>, style: Style) -> Self {
        Layer {
            name: name.into(),
            style,
            marks: Vec::new(),
        }
    }

    /// Add a mark.
    pub fn push(&mut self, mark: Mark) {
        self.marks.push(mark);
    }

    /// With a dot at `p`.
    pub fn point(mut self, p: Point2) -> Self {
        self.push(Mark::Point { at: p, label: None });
        self
    }

    /// With a dot at `p` labelled `label`.
    pub fn labeled_point(mut self, p: Point2, label: impl Into<String>) -> Self {
        self.push(Mark::Point {
            at: p,
            label: Some(label.into()),
        });
        self
    }

    /// With a dot at each of `points`.
    pub fn points(mut self, points: &[Point2]) -> Self {
        self.marks
            .extend(points.iter().map(|&at| Mark::Point { at, label: None }));
        self
    }

    /// With a dot at each of `points`, labelled with its index 0, 1, 2, …
    pub fn numbered_points(mut self, points: &[Point2]) -> Self {
        self.marks
            .extend(points.iter().enumerate().map(|(i, &at)| Mark::Point {
                at,
                label: Some(i.to_string()),
            }));
        self
    }

    /// With a segment.
    pub fn segment(mut self, s: Segment2) -> Self {
        self.push(Mark::Segment(s));
        self
    }

    /// With each of `segments`.
    pub fn segments(mut self, segments: &[Segment2]) -> Self {
        self.marks
            .extend(segments.iter().map(|&s| Mark::Segment(s)));
        self
    }

    /// With an open polyline through `points`.
    pub fn polyline(mut self, points: &[Point2]) -> Self {
        self.push(Mark::Polyline(points.to_vec()));
        self
    }

    /// With a polygon without holes whose boundary is `ring` (open: first vertex not repeated).
    pub fn ring(mut self, ring: &[Point2]) -> Self {
        self.push(Mark::Polygon(Polygon::new(ring.to_vec(), Vec::new())));
        self
    }

    /// With a polygon (holes drawn empty).
    pub fn polygon(mut self, polygon: &Polygon) -> Self {
        self.push(Mark::Polygon(polygon.clone()));
        self
    }

    /// With each of `polygons`.
    pub fn polygons(mut self, polygons: &[Polygon]) -> Self {
        self.marks
            .extend(polygons.iter().map(|p| Mark::Polygon(p.clone())));
        self
    }

    /// With free text anchored at `at`.
    pub fn text(mut self, at: Point2, text: impl Into<String>) -> Self {
        self.push(Mark::Text {
            at,
            text: text.into(),
        });
        self
    }
}

/// An SVG picture: layers drawn in order over a white background, scaled to fit
/// `width × height` pixels, with an optional title and a legend of the named layers.
///
/// ```
/// use compgeom::render::{Layer, Picture, Style};
/// use compgeom::{Point2, Polygon};
///
/// let square = Polygon::new(
///     vec![Point2::new(0.0, 0.0), Point2::new(10.0, 0.0), Point2::new(10.0, 10.0), Point2::new(0.0, 10.0)],
///     vec![vec![Point2::new(4.0, 4.0), Point2::new(6.0, 4.0), Point2::new(6.0, 6.0)]],
/// );
/// let mut pic = Picture::new(300, 300);
/// pic.add(Layer::new("square with a hole", Style::area("#1f77b4")).polygon(&square));
/// let svg = pic.to_svg_string();
/// assert!(svg.contains("fill-rule=\"evenodd\""));
/// assert!(svg.contains("square with a hole"));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    width: u32,
    height: u32,
    margin: f64,
    title: Option<String>,
    layers: Vec<Layer>,
}

/// Height reserved for the title, in pixels.
const TITLE_HEIGHT: f64 = 28.0;
/// Height of one legend row, in pixels.
const LEGEND_ROW: f64 = 18.0;
/// Approximate width of one legend character at the legend font size, in pixels.
const LEGEND_CHAR: f64 = 6.6;

impl Picture {
    /// An empty picture of `width × height` pixels (each at least 1).
    pub fn new(width: u32, height: u32) -> Self {
        Picture {
            width: width.max(1),
            height: height.max(1),
            margin: 20.0,
            title: None,
            layers: Vec::new(),
        }
    }

    /// With a title drawn at the top.
    pub fn with_title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// With a margin of `px` pixels around the drawing (default 20).
    pub fn with_margin(mut self, px: f64) -> Self {
        self.margin = length(px, 20.0);
        self
    }

    /// Add a layer on top of the others.
    pub fn add(&mut self, layer: Layer) -> &mut Self {
        self.layers.push(layer);
        self
    }

    /// The layers, bottom first.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// The bounding box, in data coordinates, of every drawable mark (empty if none).
    pub fn bbox(&self) -> Bbox2 {
        let mut b = Bbox2::EMPTY;
        for m in self.layers.iter().flat_map(|l| &l.marks) {
            if m.is_drawable() {
                for p in m.points() {
                    b.extend(p);
                }
            }
        }
        b
    }

    /// The picture as a standalone SVG document.
    pub fn to_svg_string(&self) -> String {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let legend = self.legend_entries();
        let legend_w = if legend.is_empty() {
            0.0
        } else {
            let chars = legend
                .iter()
                .map(|l| l.name.chars().count())
                .max()
                .unwrap_or(0);
            (40.0 + LEGEND_CHAR * chars as f64).min(w / 2.0)
        };
        let title_h = if self.title.is_some() {
            TITLE_HEIGHT
        } else {
            0.0
        };
        // Plot area: what is left after margin, title and legend column (at least 1 px).
        let m = self.margin.min(w / 4.0).min(h / 4.0);
        // Room between plot and legend for the labels drawn right of the rightmost points.
        let gap = if legend.is_empty() { 0.0 } else { m + 12.0 };
        let x0 = m;
        let x1 = (w - m - legend_w - gap).max(x0 + 1.0);
        let y0 = m + title_h;
        let y1 = (h - m).max(y0 + 1.0);
        let tf = Transform::fit(self.bbox(), x0, x1, y0, y1);

        let mut s = String::new();
        let _ = writeln!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" font-family=\"sans-serif\">",
            self.width, self.height, self.width, self.height
        );
        let _ = writeln!(
            s,
            "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"white\"/>",
            self.width, self.height
        );
        for (i, layer) in self.layers.iter().enumerate() {
            write_layer(&mut s, i, layer, &tf);
        }
        if let Some(t) = &self.title {
            let _ = writeln!(
                s,
                "<text class=\"title\" x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\" fill=\"#222\">{}</text>",
                num(w / 2.0),
                num(m + 18.0),
                escape(t)
            );
        }
        if !legend.is_empty() {
            write_legend(&mut s, &legend, w - m - legend_w, y0, legend_w);
        }
        s.push_str("</svg>\n");
        s
    }

    /// The layers that appear in the legend.
    fn legend_entries(&self) -> Vec<&Layer> {
        self.layers.iter().filter(|l| !l.name.is_empty()).collect()
    }
}

/// Data → screen: uniform scale, y flipped, data box centred in the plot area.
struct Transform {
    /// Half of the data centre (halves avoid overflow for coordinates near `f64::MAX`).
    half_cx: f64,
    half_cy: f64,
    /// Pixels per half data unit.
    scale2: f64,
    /// Screen centre of the plot area.
    sx: f64,
    sy: f64,
}

impl Transform {
    fn fit(b: Bbox2, x0: f64, x1: f64, y0: f64, y1: f64) -> Transform {
        let (sx, sy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        if b.is_empty() {
            return Transform {
                half_cx: 0.0,
                half_cy: 0.0,
                scale2: 0.0,
                sx,
                sy,
            };
        }
        let (half_cx, half_cy) = (b.min.x / 4.0 + b.max.x / 4.0, b.min.y / 4.0 + b.max.y / 4.0);
        // Half extents, from halves so they never overflow.
        let mut hx = b.max.x / 2.0 - b.min.x / 2.0;
        let mut hy = b.max.y / 2.0 - b.min.y / 2.0;
        // A line of points (zero extent one way) is centred; a single point too.
        if hx == 0.0 {
            hx = hy;
        }
        if hy == 0.0 {
            hy = hx;
        }
        let (pw, ph) = ((x1 - x0) / 2.0, (y1 - y0) / 2.0);
        // Screen = centre + (p/2 - c/2) * scale2, with scale2 = 2 * pixels per data unit.
        let scale = (pw / hx).min(ph / hy);
        let scale2 = if scale.is_finite() && hx > 0.0 {
            2.0 * scale
        } else {
            // Single point, or an extent so tiny the scale overflows: everything at the centre.
            0.0
        };
        Transform {
            half_cx,
            half_cy,
            scale2: if scale2.is_finite() { scale2 } else { 0.0 },
            sx,
            sy,
        }
    }

    fn apply(&self, p: Point2) -> (f64, f64) {
        let x = self.sx + (p.x / 2.0 - self.half_cx) * self.scale2;
        let y = self.sy - (p.y / 2.0 - self.half_cy) * self.scale2;
        (finite(x), finite(y))
    }
}

/// `x`, or 0 if it is not finite (cannot happen for finite input; a last guard for the output).
fn finite(x: f64) -> f64 {
    if x.is_finite() {
        x
    } else {
        0.0
    }
}

fn write_layer(s: &mut String, index: usize, layer: &Layer, tf: &Transform) {
    let st = &layer.style;
    let stroke = escape(&st.stroke);
    let sw = num(length(st.stroke_width, 1.5));
    let r = num(length(st.radius, 3.0));
    let font = num(length(st.font_size, 11.0));
    let fill = st
        .fill
        .as_deref()
        .map(escape)
        .unwrap_or_else(|| "none".to_string());
    let dash = st
        .dash
        .as_deref()
        .map(|d| format!(" stroke-dasharray=\"{}\"", escape(d)))
        .unwrap_or_default();
    let _ = write!(s, "<g id=\"layer-{index}\" class=\"layer\"");
    if unit(st.opacity) < 1.0 {
        let _ = write!(s, " opacity=\"{}\"", num(unit(st.opacity)));
    }
    s.push_str(">\n");
    if !layer.name.is_empty() {
        let _ = writeln!(s, "<title>{}</title>", escape(&layer.name));
    }
    let drawable: Vec<&Mark> = layer.marks.iter().filter(|m| m.is_drawable()).collect();

    // Areas first, then lines, then dots, then text, so nothing hides the small things.
    let polys: Vec<&Polygon> = drawable
        .iter()
        .filter_map(|m| match m {
            Mark::Polygon(p) => Some(p),
            _ => None,
        })
        .collect();
    if !polys.is_empty() {
        let _ = writeln!(
            s,
            "<g class=\"polygons\" fill=\"{fill}\" fill-opacity=\"{}\" fill-rule=\"evenodd\" stroke=\"{stroke}\" stroke-width=\"{sw}\" stroke-linejoin=\"round\"{dash}>",
            num(unit(st.fill_opacity))
        );
        for p in polys {
            let mut d = String::new();
            for ring in p.rings().filter(|r| !r.is_empty()) {
                for (k, &q) in ring.iter().enumerate() {
                    let (x, y) = tf.apply(q);
                    let _ = write!(
                        d,
                        "{}{} {} ",
                        if k == 0 { "M" } else { "L" },
                        num(x),
                        num(y)
                    );
                }
                d.push_str("Z ");
            }
            let _ = writeln!(s, "<path d=\"{}\"/>", d.trim_end());
        }
        s.push_str("</g>\n");
    }

    let has_lines = drawable
        .iter()
        .any(|m| matches!(m, Mark::Segment(_) | Mark::Polyline(_)));
    if has_lines {
        let _ = writeln!(
            s,
            "<g class=\"lines\" fill=\"none\" stroke=\"{stroke}\" stroke-width=\"{sw}\" stroke-linecap=\"round\" stroke-linejoin=\"round\"{dash}>"
        );
        for m in &drawable {
            match m {
                Mark::Segment(seg) => {
                    let (ax, ay) = tf.apply(seg.a);
                    let (bx, by) = tf.apply(seg.b);
                    let _ = writeln!(
                        s,
                        "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
                        num(ax),
                        num(ay),
                        num(bx),
                        num(by)
                    );
                }
                Mark::Polyline(v) => {
                    let pts: Vec<String> = v
                        .iter()
                        .map(|&q| {
                            let (x, y) = tf.apply(q);
                            format!("{},{}", num(x), num(y))
                        })
                        .collect();
                    let _ = writeln!(s, "<polyline points=\"{}\"/>", pts.join(" "));
                }
                _ => {}
            }
        }
        s.push_str("</g>\n");
    }

    let dots: Vec<Point2> = drawable
        .iter()
        .filter_map(|m| match m {
            Mark::Point { at, .. } => Some(*at),
            _ => None,
        })
        .collect();
    if !dots.is_empty() {
        // Unfilled dots get an outline so they stay visible.
        let outline = if st.fill.is_none() || length(st.stroke_width, 0.0) > 0.0 {
            format!(
                " stroke=\"{stroke}\" stroke-width=\"{}\"",
                num(length(st.stroke_width, 1.0).max(if st.fill.is_none() { 1.0 } else { 0.0 }))
            )
        } else {
            String::new()
        };
        let _ = writeln!(s, "<g class=\"points\" fill=\"{fill}\"{outline}>");
        for p in dots {
            let (x, y) = tf.apply(p);
            let _ = writeln!(s, "<circle cx=\"{}\" cy=\"{}\" r=\"{r}\"/>", num(x), num(y));
        }
        s.push_str("</g>\n");
    }

    let has_text = drawable
        .iter()
        .any(|m| matches!(m, Mark::Text { .. } | Mark::Point { label: Some(_), .. }));
    if has_text {
        let _ = writeln!(
            s,
            "<g class=\"labels\" fill=\"{stroke}\" font-size=\"{font}\">"
        );
        let off = length(st.radius, 3.0) + 2.0;
        for m in &drawable {
            let (at, text, dx, dy) = match m {
                Mark::Point { at, label: Some(l) } => (*at, l, off, -off),
                Mark::Text { at, text } => (*at, text, 0.0, 0.0),
                _ => continue,
            };
            let (x, y) = tf.apply(at);
            let _ = writeln!(
                s,
                "<text x=\"{}\" y=\"{}\">{}</text>",
                num(x + dx),
                num(y + dy),
                escape(text)
            );
        }
        s.push_str("</g>\n");
    }
    s.push_str("</g>\n");
}

fn write_legend(s: &mut String, entries: &[&Layer], x: f64, y: f64, w: f64) {
    let h = 8.0 + LEGEND_ROW * entries.len() as f64;
    let _ = writeln!(
        s,
        "<g class=\"legend\" font-size=\"11\">\n<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#999\" stroke-width=\"1\"/>",
        num(x),
        num(y),
        num(w),
        num(h)
    );
    for (k, layer) in entries.iter().enumerate() {
        let st = &layer.style;
        let stroke = escape(&st.stroke);
        let fill = st
            .fill
            .as_deref()
            .map(escape)
            .unwrap_or_else(|| "none".to_string());
        let cy = y + 4.0 + LEGEND_ROW * (k as f64 + 0.5);
        let (sx, sw) = (x + 8.0, 22.0);
        let kind = legend_kind(layer);
        match kind {
            LegendKind::Area => {
                let _ = writeln!(
                    s,
                    "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"10\" fill=\"{fill}\" fill-opacity=\"{}\" stroke=\"{stroke}\" stroke-width=\"{}\"/>",
                    num(sx),
                    num(cy - 5.0),
                    num(sw),
                    num(unit(st.fill_opacity)),
                    num(length(st.stroke_width, 1.5))
                );
            }
            LegendKind::Line => {
                let _ = writeln!(
                    s,
                    "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{stroke}\" stroke-width=\"{}\"/>",
                    num(sx),
                    num(cy),
                    num(sx + sw),
                    num(cy),
                    num(length(st.stroke_width, 1.5).max(1.0))
                );
            }
            LegendKind::Dot => {
                let fill = if st.fill.is_some() {
                    fill
                } else {
                    "none".into()
                };
                let _ = writeln!(
                    s,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"1\"/>",
                    num(sx + sw / 2.0),
                    num(cy),
                    num(length(st.radius, 3.0).clamp(2.0, 6.0))
                );
            }
            LegendKind::Text => {
                let _ = writeln!(
                    s,
                    "<text x=\"{}\" y=\"{}\" fill=\"{stroke}\" font-weight=\"bold\">Aa</text>",
                    num(sx + 2.0),
                    num(cy + 4.0)
                );
            }
        }
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" fill=\"#222\">{}</text>",
            num(sx + sw + 6.0),
            num(cy + 4.0),
            escape(&layer.name)
        );
    }
    s.push_str("</g>\n");
}

enum LegendKind {
    Area,
    Line,
    Dot,
    Text,
}

/// The legend symbol: the most prominent kind of mark in the layer.
fn legend_kind(layer: &Layer) -> LegendKind {
    let has = |f: fn(&Mark) -> bool| layer.marks.iter().any(f);
    if has(|m| matches!(m, Mark::Polygon(_))) {
        LegendKind::Area
    } else if has(|m| matches!(m, Mark::Segment(_) | Mark::Polyline(_))) {
        LegendKind::Line
    } else if has(|m| matches!(m, Mark::Point { .. })) || layer.marks.is_empty() {
        LegendKind::Dot
    } else {
        LegendKind::Text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transform_centres_single_point_and_flips_y() {
        let b = Bbox2::of_points(&[Point2::new(5.0, 5.0)]);
        let t = Transform::fit(b, 0.0, 100.0, 0.0, 50.0);
        assert_eq!(t.apply(Point2::new(5.0, 5.0)), (50.0, 25.0));

        let b = Bbox2::of_points(&[Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)]);
        let t = Transform::fit(b, 0.0, 100.0, 0.0, 100.0);
        assert_eq!(t.apply(Point2::new(0.0, 0.0)), (0.0, 100.0));
        assert_eq!(t.apply(Point2::new(1.0, 1.0)), (100.0, 0.0));
    }

    #[test]
    fn transform_keeps_aspect_ratio() {
        // Data 2 wide, 1 high into a 100x100 area: scale 50, vertically centred.
        let b = Bbox2::of_points(&[Point2::new(0.0, 0.0), Point2::new(2.0, 1.0)]);
        let t = Transform::fit(b, 0.0, 100.0, 0.0, 100.0);
        assert_eq!(t.apply(Point2::new(0.0, 0.0)), (0.0, 75.0));
        assert_eq!(t.apply(Point2::new(2.0, 1.0)), (100.0, 25.0));
    }

    #[test]
    fn transform_survives_extreme_extents() {
        let b = Bbox2::of_points(&[
            Point2::new(-f64::MAX, -f64::MAX),
            Point2::new(f64::MAX, f64::MAX),
        ]);
        let t = Transform::fit(b, 0.0, 100.0, 0.0, 100.0);
        let (x, y) = t.apply(Point2::new(f64::MAX, -f64::MAX));
        assert!(
            (x - 100.0).abs() < 1e-9 && (y - 100.0).abs() < 1e-9,
            "{x} {y}"
        );
        let tiny = f64::from_bits(1);
        let b = Bbox2::of_points(&[Point2::new(0.0, 0.0), Point2::new(tiny, tiny)]);
        let t = Transform::fit(b, 0.0, 100.0, 0.0, 100.0);
        let (x, y) = t.apply(Point2::new(tiny, 0.0));
        assert!(x.is_finite() && y.is_finite());
    }
}
