//! Range searching and windowing in a few lines: which points lie in a rectangle, how
//! many, which are nearest; which segments meet a window.
//!
//! ```text
//! cargo run --example range
//! ```

use compgeom::range::{KdTree, LayeredRangeTree};
use compgeom::windowing::SegmentWindow;
use compgeom::{Bbox2, Point2, Segment2};

fn main() -> compgeom::Result<()> {
    // A 10 × 10 grid with every point twice: equal coordinates everywhere.
    let points: Vec<Point2> = (0..200)
        .map(|i| Point2::new(((i / 2) % 10) as f64, ((i / 2) / 10) as f64))
        .collect();
    let rect = Bbox2 {
        min: Point2::new(2.0, 3.0),
        max: Point2::new(4.0, 3.0), // zero height: the points on a segment
    };

    let tree = LayeredRangeTree::new(&points)?;
    let inside = tree.query(&rect);
    println!(
        "layered range tree: {} points in {rect:?}: {inside:?}",
        tree.count(&rect)
    );
    assert_eq!(inside, vec![64, 65, 66, 67, 68, 69]);

    let kd = KdTree::new(&points)?;
    assert_eq!(kd.query(&rect), inside);
    let near = kd.nearest(Point2::new(4.4, 4.4), 3);
    println!("3 nearest to (4.4, 4.4): {near:?}");
    // (4, 4) twice, then (5, 4) and (4, 5) tie exactly (0.36 + 0.16 either way): the
    // smaller index, 90, wins.
    assert_eq!(near, vec![88, 89, 90]);

    // A segment that crosses the window without an endpoint inside is found.
    let segments = [
        Segment2::new(Point2::new(-1.0, 0.5), Point2::new(9.0, 0.5)),
        Segment2::new(Point2::new(5.0, 5.0), Point2::new(6.0, 6.0)),
    ];
    let windows = SegmentWindow::new(&segments)?;
    let window = Bbox2 {
        min: Point2::new(0.0, 0.0),
        max: Point2::new(1.0, 1.0),
    };
    println!("segments meeting {window:?}: {:?}", windows.query(&window));
    assert_eq!(windows.query(&window), vec![0]);
    Ok(())
}
