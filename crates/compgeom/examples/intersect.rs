//! Find the intersections of a few segments and print them.
use compgeom::intersect::find_intersections;
use compgeom::Segment2;

fn main() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    let segs = [s((0.0, 0.0), (3.0, 1.0)), s((0.0, 1.0), (3.0, 0.0))];
    let found = find_intersections(&segs).expect("finite input");
    for p in &found.points {
        println!(
            "{:?} segments {:?} U {:?} L {:?} C {:?}",
            p.point,
            p.segments(),
            p.upper(),
            p.lower(),
            p.interior()
        );
    }
}
