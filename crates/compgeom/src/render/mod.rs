//! Pictures: an SVG writer that draws points, segments, polygons, labels and a legend,
//! scaled to fit. (API skeleton; the rendering work fills it in.)
