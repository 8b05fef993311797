//! [`Gallery`]: an HTML page of pictures in sections, each with a table of its figures.

use super::xml::escape;
use std::fmt::Write as _;

/// How a figure's picture is included in the page.
#[derive(Debug, Clone, PartialEq)]
pub enum FigureImage {
    /// An SVG document, pasted into the page (the page is then self-contained).
    /// It must be trusted SVG, such as [`Picture::to_svg_string`](super::Picture::to_svg_string) returns.
    Inline(String),
    /// A relative URL or path of an image file next to the page (escaped when written).
    Linked(String),
}

/// One picture with its caption and figures (name/value pairs such as `n`, `h`, `time`).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Caption under the picture, also the row name in the section's table.
    pub caption: String,
    /// The picture.
    pub image: FigureImage,
    /// Figures for the section table, in column order.
    pub facts: Vec<(String, String)>,
}

impl Figure {
    /// A figure without facts.
    pub fn new(caption: impl Into<String>, image: FigureImage) -> Self {
        Figure {
            caption: caption.into(),
            image,
            facts: Vec::new(),
        }
    }

    /// With one more fact (a column of the section table).
    pub fn with_fact(mut self, name: impl Into<String>, value: impl Into<String>) -> Self {
        self.facts.push((name.into(), value.into()));
        self
    }
}

/// A titled section: a description (plain text; blank lines separate paragraphs), a table
/// of the figures' facts, and the pictures.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Section {
    /// Heading.
    pub title: String,
    /// Plain-text explanation.
    pub description: String,
    /// The figures, in order.
    pub figures: Vec<Figure>,
}

impl Section {
    /// An empty section.
    pub fn new(title: impl Into<String>, description: impl Into<String>) -> Self {
        Section {
            title: title.into(),
            description: description.into(),
            figures: Vec::new(),
        }
    }

    /// Add a figure.
    pub fn push(&mut self, figure: Figure) {
        self.figures.push(figure);
    }
}

/// An HTML page of [`Section`]s. The page is also well-formed XML (void elements are
/// self-closed), so tools that parse XML can check it.
///
/// ```
/// use compgeom::render::{Figure, FigureImage, Gallery, Section};
///
/// let mut g = Gallery::new("demo");
/// let mut s = Section::new("Chapter 1", "Hulls.");
/// s.push(Figure::new("disc", FigureImage::Linked("disc.svg".into())).with_fact("n", "200"));
/// g.push(s);
/// let html = g.to_html_string();
/// assert!(html.contains("<img src=\"disc.svg\""));
/// assert!(html.contains("<td>200</td>"));
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Gallery {
    /// Page title and top heading.
    pub title: String,
    /// Plain-text introduction under the heading.
    pub intro: String,
    /// The sections, in order.
    pub sections: Vec<Section>,
}

impl Gallery {
    /// An empty gallery.
    pub fn new(title: impl Into<String>) -> Self {
        Gallery {
            title: title.into(),
            ..Gallery::default()
        }
    }

    /// With an introduction.
    pub fn with_intro(mut self, intro: impl Into<String>) -> Self {
        self.intro = intro.into();
        self
    }

    /// Add a section.
    pub fn push(&mut self, section: Section) {
        self.sections.push(section);
    }

    /// The page as a standalone HTML5 document.
    pub fn to_html_string(&self) -> String {
        let mut s = String::new();
        let title = escape(&self.title);
        let _ = writeln!(
            s,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>{title}</title>\n<style>\n{CSS}</style>\n</head>\n<body>\n<h1>{title}</h1>"
        );
        paragraphs(&mut s, &self.intro);
        if self.sections.len() > 1 {
            s.push_str("<nav><ul>\n");
            for (i, sec) in self.sections.iter().enumerate() {
                let _ = writeln!(
                    s,
                    "<li><a href=\"#section-{i}\">{}</a></li>",
                    escape(&sec.title)
                );
            }
            s.push_str("</ul></nav>\n");
        }
        for (i, sec) in self.sections.iter().enumerate() {
            write_section(&mut s, i, sec);
        }
        s.push_str("</body>\n</html>\n");
        s
    }
}

const CSS: &str = "body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
figure { display: inline-block; margin: 0.5em; vertical-align: top; }
figure img, figure svg { border: 1px solid #ddd; max-width: 100%; height: auto; }
figcaption { font-size: 0.9em; color: #444; max-width: 520px; }
";

fn paragraphs(s: &mut String, text: &str) {
    for p in text.split("\n\n").map(str::trim).filter(|p| !p.is_empty()) {
        let _ = writeln!(s, "<p>{}</p>", escape(p));
    }
}

fn write_section(s: &mut String, index: usize, sec: &Section) {
    let _ = writeln!(
        s,
        "<section id=\"section-{index}\">\n<h2>{}</h2>",
        escape(&sec.title)
    );
    paragraphs(s, &sec.description);
    // Table columns: every fact name, in order of first appearance.
    let mut columns: Vec<&str> = Vec::new();
    for f in &sec.figures {
        for (name, _) in &f.facts {
            if !columns.contains(&name.as_str()) {
                columns.push(name);
            }
        }
    }
    if !sec.figures.is_empty() {
        s.push_str("<table>\n<tr><th>figure</th>");
        for c in &columns {
            let _ = write!(s, "<th>{}</th>", escape(c));
        }
        s.push_str("</tr>\n");
        for f in &sec.figures {
            let _ = write!(s, "<tr><td>{}</td>", escape(&f.caption));
            for c in &columns {
                let v = f
                    .facts
                    .iter()
                    .find(|(n, _)| n == c)
                    .map(|(_, v)| escape(v))
                    .unwrap_or_default();
                let _ = write!(s, "<td>{v}</td>");
            }
            s.push_str("</tr>\n");
        }
        s.push_str("</table>\n");
    }
    for f in &sec.figures {
        s.push_str("<figure>\n");
        match &f.image {
            FigureImage::Inline(svg) => {
                // Drop an XML declaration if any: it is not allowed inside HTML.
                let svg = svg.trim_start();
                let svg = match svg.strip_prefix("<?xml") {
                    Some(rest) => rest.split_once("?>").map_or(svg, |(_, r)| r),
                    None => svg,
                };
                s.push_str(svg.trim());
                s.push('\n');
            }
            FigureImage::Linked(url) => {
                let url = escape(url);
                let _ = writeln!(
                    s,
                    "<a href=\"{url}\"><img src=\"{url}\" alt=\"{}\"/></a>",
                    escape(&f.caption)
                );
            }
        }
        let _ = writeln!(
            s,
            "<figcaption>{}</figcaption>\n</figure>",
            escape(&f.caption)
        );
    }
    s.push_str("</section>\n");
}
