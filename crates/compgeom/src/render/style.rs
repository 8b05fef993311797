//! How a layer is drawn.

/// The look of one layer. Colours are CSS colours (`"#1f77b4"`, `"red"`); lengths are screen
/// pixels (not scaled with the data).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Style {
    /// Stroke colour of lines and outlines, and the colour of text and labels.
    pub stroke: String,
    /// Fill colour of polygons and points; `None` leaves them unfilled.
    pub fill: Option<String>,
    /// Line width in pixels.
    pub stroke_width: f64,
    /// Point radius in pixels.
    pub radius: f64,
    /// Opacity of the whole layer, 0 to 1.
    pub opacity: f64,
    /// Opacity of polygon fills, 0 to 1.
    pub fill_opacity: f64,
    /// Dash pattern for lines, e.g. `"4 3"`; `None` draws solid lines.
    pub dash: Option<String>,
    /// Font size of labels and text marks, in pixels.
    pub font_size: f64,
}

impl Default for Style {
    fn default() -> Self {
        Style {
            stroke: "#333333".to_string(),
            fill: None,
            stroke_width: 1.5,
            radius: 3.0,
            opacity: 1.0,
            fill_opacity: 0.25,
            dash: None,
            font_size: 11.0,
        }
    }
}

impl Style {
    /// Filled dots of `color`.
    pub fn points(color: &str) -> Self {
        Style {
            stroke: color.to_string(),
            fill: Some(color.to_string()),
            stroke_width: 0.0,
            ..Style::default()
        }
    }

    /// Lines of `color`, unfilled.
    pub fn lines(color: &str) -> Self {
        Style {
            stroke: color.to_string(),
            ..Style::default()
        }
    }

    /// Areas outlined in `color` and filled with it, translucent.
    pub fn area(color: &str) -> Self {
        Style {
            stroke: color.to_string(),
            fill: Some(color.to_string()),
            ..Style::default()
        }
    }

    /// Text in `color`.
    pub fn text(color: &str) -> Self {
        Style {
            stroke: color.to_string(),
            stroke_width: 0.0,
            ..Style::default()
        }
    }

    /// With line width `w` pixels.
    pub fn with_stroke_width(mut self, w: f64) -> Self {
        self.stroke_width = w;
        self
    }

    /// With point radius `r` pixels.
    pub fn with_radius(mut self, r: f64) -> Self {
        self.radius = r;
        self
    }

    /// With fill colour `color`.
    pub fn with_fill(mut self, color: &str) -> Self {
        self.fill = Some(color.to_string());
        self
    }

    /// Without fill.
    pub fn without_fill(mut self) -> Self {
        self.fill = None;
        self
    }

    /// With layer opacity `o` (clamped to 0..=1 when drawn).
    pub fn with_opacity(mut self, o: f64) -> Self {
        self.opacity = o;
        self
    }

    /// With fill opacity `o` (clamped to 0..=1 when drawn).
    pub fn with_fill_opacity(mut self, o: f64) -> Self {
        self.fill_opacity = o;
        self
    }

    /// With dash pattern `pattern` (SVG `stroke-dasharray`, e.g. `"4 3"`).
    pub fn with_dash(mut self, pattern: &str) -> Self {
        self.dash = Some(pattern.to_string());
        self
    }

    /// With font size `px`.
    pub fn with_font_size(mut self, px: f64) -> Self {
        self.font_size = px;
        self
    }
}

/// A length for output: finite and non-negative, else `default`.
pub(crate) fn length(x: f64, default: f64) -> f64 {
    if x.is_finite() && x >= 0.0 {
        x
    } else {
        default
    }
}

/// An opacity for output, clamped to 0..=1 (`NaN` → 1).
pub(crate) fn unit(x: f64) -> f64 {
    if x.is_nan() {
        1.0
    } else {
        x.clamp(0.0, 1.0)
    }
}
