//! The SVG writer and the HTML gallery: well-formed output, y up, fit to the canvas,
//! legend and title, escaping, and degenerate extents without NaN.

use compgeom::render::{Figure, FigureImage, Gallery, Layer, Picture, Section, Style};
use compgeom::{Point2, Polygon, Segment2};
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

/// Parse `svg`, panicking with the text if it is not well-formed XML.
fn parse(svg: &str) -> roxmltree::Document<'_> {
    match roxmltree::Document::parse(svg) {
        Ok(d) => d,
        Err(e) => panic!("not well-formed XML ({e}):\n{svg}"),
    }
}

fn attr(n: &roxmltree::Node, name: &str) -> f64 {
    n.attribute(name)
        .unwrap_or_else(|| panic!("missing {name}"))
        .parse()
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The centres of the circles of the `index`-th layer.
fn circles(doc: &roxmltree::Document, index: usize) -> Vec<(f64, f64)> {
    let id = format!("layer-{index}");
    let layer = doc
        .descendants()
        .find(|n| n.attribute("id") == Some(id.as_str()))
        .expect("layer group");
    layer
        .descendants()
        .filter(|n| n.has_tag_name("circle"))
        .map(|n| (attr(&n, "cx"), attr(&n, "cy")))
        .collect()
}

/// Every numeric coordinate attribute and path/polyline number of the document.
fn all_numbers(doc: &roxmltree::Document) -> Vec<f64> {
    let mut out = Vec::new();
    for n in doc.descendants().filter(|n| n.is_element()) {
        for a in n.attributes() {
            match a.name() {
                "x" | "y" | "cx" | "cy" | "x1" | "y1" | "x2" | "y2" | "r" | "width" | "height" => {
                    out.push(a.value().parse::<f64>().expect("number"))
                }
                "d" | "points" => out.extend(
                    a.value()
                        .split(|c: char| c == ' ' || c == ',' || c.is_ascii_alphabetic())
                        .filter(|t| !t.is_empty())
                        .map(|t| t.parse::<f64>().expect("number")),
                ),
                _ => {}
            }
        }
    }
    out
}

/// Checks every picture must pass: well-formed, svg root, no NaN/inf, everything on the canvas.
fn check_sane(pic: &Picture, w: f64, h: f64) -> String {
    let svg = pic.to_svg_string();
    assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
    let doc = parse(&svg);
    let root = doc.root_element();
    assert!(root.has_tag_name(("http://www.w3.org/2000/svg", "svg")));
    assert_eq!(attr(&root, "width"), w);
    assert_eq!(attr(&root, "height"), h);
    for v in all_numbers(&doc) {
        assert!(
            v.is_finite() && v >= 0.0 && v <= w.max(h),
            "{v} off canvas in\n{svg}"
        );
    }
    svg
}

#[test]
fn y_axis_points_up_and_x_right() {
    let mut pic = Picture::new(200, 200);
    pic.add(Layer::new("pts", Style::points("black")).points(&[p(0.0, 0.0), p(1.0, 1.0)]));
    let svg = check_sane(&pic, 200.0, 200.0);
    let doc = parse(&svg);
    let c = circles(&doc, 0);
    assert_eq!(c.len(), 2);
    assert!(c[0].0 < c[1].0, "x grows to the right: {c:?}");
    assert!(c[0].1 > c[1].1, "y grows upwards (smaller screen y): {c:?}");
}

#[test]
fn aspect_ratio_is_kept() {
    // A unit square in a wide canvas stays a square on screen.
    let sq = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
    let mut pic = Picture::new(600, 200);
    pic.add(Layer::new("", Style::points("black")).points(&sq));
    let svg = check_sane(&pic, 600.0, 200.0);
    let c = circles(&parse(&svg), 0);
    let dx = c[1].0 - c[0].0;
    let dy = c[0].1 - c[3].1;
    assert!(dx > 100.0, "{c:?}");
    assert!((dx - dy).abs() < 0.02, "not square on screen: {dx} vs {dy}");
}

#[test]
fn widths_and_radii_are_in_screen_units() {
    let draw = |scale: f64| {
        let mut pic = Picture::new(300, 300);
        pic.add(
            Layer::new("l", Style::lines("red").with_stroke_width(2.5))
                .segment(Segment2::new(p(0.0, 0.0), p(scale, scale))),
        );
        pic.add(Layer::new("d", Style::points("blue").with_radius(4.0)).point(p(scale, 0.0)));
        pic.to_svg_string()
    };
    let (a, b) = (draw(1e-6), draw(1e6));
    assert_eq!(a, b, "same picture whatever the data scale");
    assert!(a.contains("stroke-width=\"2.5\""));
    assert!(a.contains("r=\"4\""));
}

#[test]
fn legend_and_title_are_present_and_escaped() {
    let mut pic = Picture::new(400, 300).with_title("hull <n = 3> & \"h\"");
    pic.add(Layer::new("input points", Style::points("#777")).points(&[p(0.0, 0.0)]));
    pic.add(Layer::new("hull", Style::area("#1f77b4")).ring(&[
        p(0.0, 0.0),
        p(1.0, 0.0),
        p(0.0, 1.0),
    ]));
    pic.add(Layer::new("edges", Style::lines("red")).polyline(&[p(0.0, 0.0), p(1.0, 0.0)]));
    pic.add(Layer::new("", Style::text("green")).text(p(0.5, 0.5), "a<b"));
    let svg = check_sane(&pic, 400.0, 300.0);
    let doc = parse(&svg);
    let title = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("title"))
        .expect("title");
    assert_eq!(title.text(), Some("hull <n = 3> & \"h\""));
    let legend = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("legend"))
        .expect("legend");
    let names: Vec<&str> = legend
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect();
    assert_eq!(
        names,
        ["input points", "hull", "edges"],
        "unnamed layers are not listed"
    );
    // One symbol per entry: a dot, an area, a line.
    assert_eq!(
        legend
            .descendants()
            .filter(|n| n.has_tag_name("circle"))
            .count(),
        1
    );
    assert_eq!(
        legend
            .descendants()
            .filter(|n| n.has_tag_name("line"))
            .count(),
        1
    );
    // Background + legend box + the area symbol.
    assert_eq!(
        legend
            .descendants()
            .filter(|n| n.has_tag_name("rect"))
            .count(),
        2
    );
    let free_text: Vec<&str> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("labels"))
        .flat_map(|g| {
            g.children()
                .filter(|n| n.is_element())
                .filter_map(|n| n.text())
        })
        .collect();
    assert_eq!(free_text, ["a<b"]);
}

#[test]
fn numbered_points_carry_their_index() {
    let pts = [p(3.0, 1.0), p(0.0, 0.0), p(2.0, 5.0)];
    let mut pic = Picture::new(300, 300);
    pic.add(Layer::new("hull vertices", Style::points("red")).numbered_points(&pts));
    let svg = check_sane(&pic, 300.0, 300.0);
    let doc = parse(&svg);
    let labels: Vec<&str> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("labels"))
        .flat_map(|g| {
            g.children()
                .filter(|n| n.is_element())
                .filter_map(|n| n.text())
        })
        .collect();
    assert_eq!(labels, ["0", "1", "2"]);
}

#[test]
fn polygons_with_holes_use_even_odd() {
    let poly = Polygon::new(
        vec![p(0.0, 0.0), p(10.0, 0.0), p(10.0, 10.0), p(0.0, 10.0)],
        vec![
            vec![p(2.0, 2.0), p(4.0, 2.0), p(4.0, 4.0)],
            vec![p(6.0, 6.0), p(8.0, 6.0), p(8.0, 8.0)],
        ],
    );
    let mut pic = Picture::new(300, 300);
    pic.add(Layer::new("polygon", Style::area("teal")).polygon(&poly));
    let svg = check_sane(&pic, 300.0, 300.0);
    let doc = parse(&svg);
    let path = doc
        .descendants()
        .find(|n| n.has_tag_name("path"))
        .expect("path");
    let d = path.attribute("d").unwrap();
    assert_eq!(d.matches('M').count(), 3, "{d}");
    assert_eq!(d.matches('Z').count(), 3, "{d}");
    let group = path.parent().unwrap();
    assert_eq!(group.attribute("fill-rule"), Some("evenodd"));
}

#[test]
fn degenerate_extents_are_centred_without_nan() {
    // Empty picture.
    check_sane(&Picture::new(100, 80), 100.0, 80.0);
    check_sane(&Picture::new(100, 80).with_title("empty"), 100.0, 80.0);
    // An empty layer.
    let mut pic = Picture::new(100, 80);
    pic.add(Layer::new("nothing", Style::points("red")));
    check_sane(&pic, 100.0, 80.0);

    // One point (several times): drawn in the middle of the plot area.
    let mut pic = Picture::new(200, 200);
    pic.add(Layer::new("", Style::points("red")).points(&[p(7.0, -3.0), p(7.0, -3.0)]));
    let svg = check_sane(&pic, 200.0, 200.0);
    let c = circles(&parse(&svg), 0);
    assert_eq!(c, [(100.0, 100.0), (100.0, 100.0)]);

    // Horizontal and vertical lines of points: spread along the line, centred across it.
    for (pts, horizontal) in [
        (vec![p(0.0, 5.0), p(1.0, 5.0), p(3.0, 5.0)], true),
        (vec![p(5.0, 0.0), p(5.0, 1.0), p(5.0, 3.0)], false),
    ] {
        let mut pic = Picture::new(200, 200);
        pic.add(Layer::new("", Style::points("red")).points(&pts));
        let svg = check_sane(&pic, 200.0, 200.0);
        let c = circles(&parse(&svg), 0);
        for &(x, y) in &c {
            let across = if horizontal { y } else { x };
            assert_eq!(across, 100.0, "{c:?}");
        }
        let along: Vec<f64> = c
            .iter()
            .map(|&(x, y)| if horizontal { x } else { -y })
            .collect();
        assert!(along[0] < along[1] && along[1] < along[2], "{c:?}");
    }

    // Extreme magnitudes.
    for pts in [
        vec![p(-f64::MAX, -f64::MAX), p(f64::MAX, f64::MAX), p(0.0, 0.0)],
        vec![p(0.0, 0.0), p(f64::from_bits(1), f64::from_bits(3))],
        vec![p(1e300, 1e-300), p(1e300, 2e-300)],
    ] {
        let mut pic = Picture::new(200, 200);
        pic.add(Layer::new("x", Style::points("red")).points(&pts));
        pic.add(Layer::new("y", Style::area("blue")).ring(&pts));
        check_sane(&pic, 200.0, 200.0);
    }
}

#[test]
fn marks_with_non_finite_coordinates_are_skipped() {
    let mut pic = Picture::new(200, 200);
    pic.add(
        Layer::new("pts", Style::points("red"))
            .points(&[
                p(0.0, 0.0),
                p(f64::NAN, 1.0),
                p(1.0, f64::INFINITY),
                p(1.0, 1.0),
            ])
            .segment(Segment2::new(p(0.0, 0.0), p(f64::NEG_INFINITY, 0.0))),
    );
    let svg = check_sane(&pic, 200.0, 200.0);
    let doc = parse(&svg);
    assert_eq!(circles(&doc, 0).len(), 2);
    let layer = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("layer-0"))
        .unwrap();
    assert_eq!(
        layer
            .descendants()
            .filter(|n| n.has_tag_name("line"))
            .count(),
        0
    );
    assert_eq!(pic.bbox().max, p(1.0, 1.0));
}

#[test]
fn tiny_canvas_is_still_sane() {
    let mut pic = Picture::new(0, 3).with_title("t");
    pic.add(Layer::new("a very long legend entry name", Style::points("red")).point(p(1.0, 2.0)));
    let svg = pic.to_svg_string();
    assert!(!svg.contains("NaN"));
    parse(&svg);
}

#[test]
fn gallery_is_well_formed_and_lists_figures() {
    let mut pic = Picture::new(120, 100).with_title("inline");
    pic.add(Layer::new("pts", Style::points("red")).points(&[p(0.0, 0.0), p(1.0, 2.0)]));
    let mut g = Gallery::new("compgeom <demo>").with_intro("First paragraph.\n\nSecond & last.");
    let mut s = Section::new("Chapter 1 — convex hull", "Hulls of points.");
    s.push(
        Figure::new("disc", FigureImage::Linked("hull disc.svg".into()))
            .with_fact("n", "200")
            .with_fact("h", "17"),
    );
    s.push(
        Figure::new("inline", FigureImage::Inline(pic.to_svg_string()))
            .with_fact("n", "2")
            .with_fact("time", "1 µs"),
    );
    g.push(s);
    g.push(Section::new("Empty", ""));
    let html = g.to_html_string();
    // The page starts with `<!DOCTYPE html>`, which an XML parser must be told to accept.
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let doc = roxmltree::Document::parse_with_options(&html, opts)
        .unwrap_or_else(|e| panic!("not well-formed ({e}):\n{html}"));
    assert_eq!(doc.root_element().tag_name().name(), "html");
    let h1 = doc.descendants().find(|n| n.has_tag_name("h1")).unwrap();
    assert_eq!(h1.text(), Some("compgeom <demo>"));
    let ps: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("p"))
        .filter_map(|n| n.text())
        .collect();
    assert_eq!(
        ps,
        ["First paragraph.", "Second & last.", "Hulls of points."]
    );
    let table = doc.descendants().find(|n| n.has_tag_name("table")).unwrap();
    let rows: Vec<Vec<String>> = table
        .children()
        .filter(|n| n.has_tag_name("tr"))
        .map(|r| {
            r.children()
                .filter(|c| c.is_element())
                .map(|c| c.text().unwrap_or("").to_string())
                .collect()
        })
        .collect();
    assert_eq!(
        rows,
        [
            vec!["figure", "n", "h", "time"],
            vec!["disc", "200", "17", ""],
            vec!["inline", "2", "", "1 µs"],
        ]
    );
    let img = doc.descendants().find(|n| n.has_tag_name("img")).unwrap();
    assert_eq!(img.attribute("src"), Some("hull disc.svg"));
    assert_eq!(
        doc.descendants()
            .filter(|n| n.tag_name().name() == "svg")
            .count(),
        1
    );
    assert_eq!(
        doc.descendants()
            .filter(|n| n.has_tag_name("section"))
            .count(),
        2
    );
    assert_eq!(
        doc.descendants().filter(|n| n.has_tag_name("nav")).count(),
        1
    );
}

/// Coordinates from a small grid (collinear runs, duplicates), a wide float range, or exact
/// extremes: the degenerate and the ordinary.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-3i32..=3).prop_map(f64::from),
        -1e6f64..1e6,
        prop::sample::select(vec![0.0, -0.0, 1e-300, -1e300, f64::MAX, -f64::MAX, 5e-324]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn any_points_give_sane_svg(
        pts in prop::collection::vec((coord(), coord()).prop_map(|(x, y)| Point2::new(x, y)), 0..20),
        w in 120u32..900,
        h in 120u32..900,
    ) {
        let mut pic = Picture::new(w, h).with_title("random");
        pic.add(Layer::new("area", Style::area("blue")).ring(&pts));
        pic.add(Layer::new("line", Style::lines("green")).polyline(&pts));
        pic.add(Layer::new("dots", Style::points("red")).numbered_points(&pts));
        let svg = pic.to_svg_string();
        prop_assert!(!svg.contains("NaN") && !svg.contains("inf"));
        let doc = parse(&svg);
        for v in all_numbers(&doc) {
            prop_assert!(v.is_finite() && v >= 0.0 && v <= f64::from(w.max(h)), "{} off canvas", v);
        }
        prop_assert_eq!(circles(&doc, 2).len(), pts.len());
        // Order along x and y is preserved on screen (y flipped), so the picture is faithful.
        let c = circles(&doc, 2);
        for i in 0..pts.len() {
            for j in 0..pts.len() {
                if pts[i].x < pts[j].x { prop_assert!(c[i].0 <= c[j].0); }
                if pts[i].y < pts[j].y { prop_assert!(c[i].1 >= c[j].1); }
            }
        }
    }
}
