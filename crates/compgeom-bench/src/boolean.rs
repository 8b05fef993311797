//! `compgeom-bench boolean`: polygon boolean operations (book §2.4) against i_overlay and
//! geo's `BooleanOps` (which runs i_overlay underneath, plus conversions).
//!
//! Inputs: two random star polygons (vertices at sorted random angles, radius
//! 0.8 + 0.15·sin 5θ plus noise of the order of 1/n, centres 0.3 apart: O(n) crossings) with n = 1e3, 1e4, 1e5 vertices, all four operations;
//! the union of 1e4 random overlapping squares (compgeom `union_all`, i_overlay's union
//! of one subject under the non-zero rule, geo's `unary_union`). compgeom is exact (crossings
//! decided exactly and rounded correctly); i_overlay snaps to an integer grid. Answers
//! are compared once, outside the clock, by area (relative difference reported); the
//! JTS pairs' and the dissolve's answers of all three are also checked for validity
//! (`validity_problems`, OGC rules, ring orientation aside), and the line under the row
//! says how many were not valid. The
//! three are timed in alternating rounds (best of 5), so load spikes hit all alike.
//!
//! Real maps (see `real_maps.rs`, read in place from the cases folder, skipped when it is
//! absent; `BOOLEAN_ROWS=stars,squares,maps` picks rows): earcut's water body against a
//! shifted copy (12.9 k vertices, 1.4 k island holes each), the 52 polygon–polygon pairs
//! of JTS's robust/overlay regressions (times summed), and GEOS ticket 837's dissolve.
//! Columns give the ratio of best times and, in brackets, the median of per-round ratios;
//! "in a row" gives compgeom / i_overlay and compgeom / geo of the median call of eight
//! consecutive calls of each (how an application calling one library over and over
//! sees it: arrays reused, memory not handed back between calls).
//!
//! End of session 7, all branches merged, machine quiet (load 2.5 falling), full run,
//! ratio compgeom / peer of best times (median of per-round ratios): star 1e3
//! 1.12–1.21 (1.14–1.21) against i_overlay and 1.10–1.19 against geo; star 1e4
//! 0.89–1.00 / 0.86–1.01; star 1e5 0.84–0.96 / 0.78–0.87; squares 2.21 / 2.16 in the
//! full run (79 ms) and 1.63–1.66 / 1.65–1.80 alone (`BOOLEAN_ROWS=squares`, 63 ms,
//! a different random input); water 0.90–1.10 / 0.95–1.16; JTS robust pairs ×52
//! 1.42–1.50 / 1.36–1.46; GEOS-837 dissolve 2.50 / 2.27 (1.13 ms against 0.45).
//!
//! Session 8 (branches s8-small and s8-squares merged; quiet machine, load 0.5–2, three
//! full runs, ratio compgeom / peer of best times, medians of per-round ratios in
//! brackets): star 1e3 0.91–1.07 (0.91–1.12) against i_overlay and 0.89–1.12 against
//! geo (xor is the one above 1); star 1e4 0.65–0.78 / 0.57–0.80; star 1e5 0.55–0.76 /
//! 0.63–0.87; squares 1.20–1.35 (1.20–1.37) / 1.08–1.22; water 0.82–1.49 / 0.78–1.39
//! (the session-7 binary alternated with this one: 1.01–1.32 against 0.82–1.49, the
//! same within noise); JTS ×52 1.14–1.32 / 1.07–1.32; GEOS-837 dissolve 2.00–2.10
//! (1.0–1.3 ms against 0.46–0.67) / 1.62–1.91, the session-7 binary 2.45–2.54 in the
//! same runs. Squares: the axis-parallel sweep now runs over y-sorted horizontals in a
//! two-level bit set with cuts as per-line keys from a compact contact list (peak
//! memory 55 → 36 MB, instructions 368.5M → 338.2M against i_overlay's 313.7M). Small
//! inputs: oriented segments without ring copies, identical segments recorded as
//! overlaps without exact tests, branch-free box tests in the noding sweep (−37% branch
//! mispredictions on star 1e3), a fast hash for merged pieces (dissolve 9.79M → 9.10M
//! instructions per call; i_overlay 4.05M). Still above 1 against geo: squares, water,
//! JTS, dissolve.
//!
//! Session 9 (branches s9-dissolve, s9-trace, s9-squares merged; quiet machine, load
//! about 1, two full runs, ratio compgeom / peer of best times, medians in brackets):
//! star 1e3 0.84–0.91 (0.84–0.92) against i_overlay and 0.83–0.89 against geo; star 1e4
//! 0.52–0.67 / 0.52–0.68; star 1e5 0.50–0.63 / 0.53–0.63; squares 1.04–1.09 (1.02–1.07)
//! / 0.89–0.99 (29–32 ms); water 0.66–0.85 / 0.66–0.80; JTS ×52 1.06–1.14 / 1.01–1.11;
//! GEOS-837 dissolve 1.87–1.88 / 1.68–1.70 (0.80–0.83 ms against 0.43–0.44). The same
//! machine, quiet, on the session-8 main at the start of the session: squares 1.26 /
//! 1.14, water 0.94–1.27 / 0.82–1.23, JTS 1.20–1.28 / 1.02–1.22, dissolve 1.94 / 1.83.
//! Noding in horizontal strips when one x-sweep strip would look at many pairs apart
//! in y (dissolve 58.7k → ~14.6k pairs looked at; water stays in the sweep instead of
//! the grid); a float filter before the exact slope comparison in the angle order at
//! vertices; the nearest-edge strips of the tracer filled from one radix-sorted x order
//! (water ~15M → ~1M instructions per call); the axis-parallel path keeps its vertices
//! as plain input points (squares 315M → 296M instructions per call, i_overlay ~297M;
//! peak memory 38 → 28 MB). Still above 1 against geo: JTS, dissolve.
//!
//! Measured, session 7 (load average 1.8 falling from 4, two runs, ms best of 5):
//!
//! | input | compgeom | i_overlay | geo | /i_overlay (median) | /geo (median) | before /i_overlay |
//! |---|---:|---:|---:|---:|---:|---:|
//! | water ∩ shifted, 4 ops | 15.5–23.6 | 13.6–19.9 | 14.1–20.5 | 1.02–1.38 (1.03–1.32) | 0.88–1.42 (1.03–1.39) | 2.9–4.1 (load 4–6) |
//! | jts robust AA ×52, 4 ops | 1.8–2.5 | 1.1–1.6 | 1.1–1.6 | 1.59–1.79 (1.59–1.76) | 1.48–1.79 | 1.62–1.74 |
//! | geos-837 dissolve | 1.4–1.6 | 0.48–0.52 | 0.51–0.62 | 2.95–3.05 | 2.58–2.76 | 3.0 |
//! | union of squares | 84–102 | 35–43 | 32–33 | 2.35–2.38 (2.26–2.28) | 2.56–3.17 | (unchanged, 459 M instr.) |
//!
//! Squares, axis-parallel arrangement (`dcel/flat.rs`, session 7 branch s7-squares;
//! callgrind, `BOOLEAN_N=10000 BOOLEAN_ONE=ours|io BOOLEAN_INPUT=squares`, whole
//! program, input generation included): 459 M → 382 M (vertices kept as plain points
//! until `finish`, a fifth of the bytes; edge reorder by a counting sort on segment
//! index instead of an indirect comparison sort; the horizontal cuts' vertex look-up
//! gallops along the vertical lines) → 368 M (the line keys sorted directly, not
//! indices looked up per comparison); i_overlay 314 M in the same build. Of ours,
//! `Flat::of_segments` is 204 M, the traced rings 137 M. Wall time under load average
//! 6–10 (other helpers' builds): 97–126 ms against i_overlay's 50–75 ms, 1.5–2.1×
//! (medians 1.7–2.0); too noisy to separate from the quiet 2.2× of main.
//!
//! Water union, callgrind: the boolean was 289 M instructions (the hole sweep 165 M, of
//! it 116 M exact orientations of crossings against the edges ending at them), now
//! 105 M (the sweep's edge-end shortcut, then the face around each component found by
//! the nearest edge west of it over x-sorted strips, no sweep); i_overlay's overlay
//! 53 M. Area deviation from i_overlay: 1e-10 on water; up to 1.7e-6 of the inputs'
//! area on JTS pairs far from the origin (i_overlay snaps to a 32-bit grid scaled to
//! the largest coordinate: cells near 1e-3 at 5.4e6; the check allows a few cells along
//! the perimeter). Stars at the same time: 1e3 1.6–1.7, 1e4 1.2–1.4, 1e5 0.97–1.74.
//!
//! Earlier (release, shared 2-core machine with other jobs running, load average 5–6 at
//! the time; ms, best of 5 alternating rounds, two runs; ratio = compgeom / peer, below 1
//! = compgeom faster; "before" = the same group before the traced boolean path, quiet
//! machine):
//!
//! | input | n | compgeom | i_overlay | geo | /i_overlay | /geo | before /i_overlay |
//! |---|---:|---:|---:|---:|---:|---:|---:|
//! | star, 4 ops | 1e3 | 0.36–0.51 | 0.19–0.40 | 0.20–0.39 | 1.24–1.85 | 1.29–1.82 | 2.6–2.9 |
//! | star, 4 ops | 1e4 | 4.3–6.6 (one 14) | 3.8–6.1 | 3.7–5.9 | 1.00–1.37 (one 2.4) | 1.08–1.24 (one 2.1) | 1.8–2.1 |
//! | star, 4 ops | 1e5 | 47–70 | 31–55 | 30–54 | 1.12–1.51 | 1.00–1.54 | 2.5–3.0 |
//! | union of squares | 1e4 | 62–96 | 31–44 | 33–39 | 2.0–2.2 | 1.9–2.5 | 5.4 |
//!
//! CPU time (`perf stat` task-clock, `BOOLEAN_ONE`, input generation included): star 1e5
//! union 107 ms against i_overlay's 93; squares 116–140 ms against 51–63.
//! Callgrind (`BOOLEAN_ONE=ours|io`, one thread, all threads counted): star 1e5 union
//! about 455 M instructions for compgeom (was about 505 M) and about 450 M for i_overlay
//! (which runs much of its work on the rayon pool, so its wall time gains more from the
//! second core); squares 477 M for compgeom (was about 860 M with the worker thread)
//! against about 300 M for i_overlay. Star 1e5 union by stage: noding about 295 M (grid,
//! pair scan, cuts), traced rings 149 M (was 213 M for DCEL linking, labels and output).
//! Squares: the hole sweep (267 M) is gone (labels of separate components come from
//! winding counts over horizontal strips), the global vertex sort of the axis-parallel
//! arrangement is replaced by binary searches along lines (their key array kept
//! contiguous: the first version missed cache and was slower in wall time despite fewer
//! instructions). Our squares IPC is lower than i_overlay's (3× the CPU time for 1.6×
//! the instructions; 18 k page faults against 7 k).
//!
//! Star rows after the x-interval-sweep noding (`dcel/noding.rs`: candidate pairs from a
//! bucketed x-sweep instead of the grid, consecutive ring edges decided by one static
//! orientation filter, assembly in plain passes; shared machine, load average 8.9–9.0
//! for two runs and 2.9–3.0 for a third, `BOOLEAN_ROWS=stars`, ratio of best times with the median of per-round
//! ratios in brackets, ranges over the four operations):
//!
//! | n | compgeom ms | i_overlay ms | /i_overlay | /geo |
//! |---:|---:|---:|---:|---:|
//! | 1e3 | 0.26–0.39 | 0.23–0.37 | 0.99–1.17 (1.01–1.15) | 0.98–1.15 (1.02–1.12) |
//! | 1e4 | 3.2–5.9 | 3.4–8.7 | 0.59–1.00 (0.54–1.03) | 0.50–1.08 (0.71–0.96) |
//! | 1e5 | 30–76 | 40–125 | 0.60–0.85 (0.62–0.85) | 0.46–0.90 (0.55–0.80) |
//!
//! Callgrind (`BOOLEAN_ONE`, one thread, input generation included): star 1e3 union
//! 4.54 M instructions against i_overlay's 4.48 M; star 1e5 union 429 M against 571 M.
//! Per `boolean` call (examples/boolean_profile): 1e3 4.66 M → 3.23 M (arrangement,
//! `Flat::of_segments`, 2.68 M → 1.26 M); 1e5 357 M → 256 M (181 M → 79 M). The
//! noding's pair tests run on the pool from 16 k segments; its assembly (44 M at 1e5)
//! is serial.
//!
//! GEOS-837 dissolve (`union_all`, 2580 vertices), `BOOLEAN_ONE=ours|io
//! BOOLEAN_INPUT=dissolve BOOLEAN_REPS=20` under callgrind (input parsing included, 20
//! calls): before, 274.5 M against i_overlay's 88.1 M; 28 % of ours was
//! `compare_coord`'s big-number fallback (~16 k instructions a call) on crossings that
//! are equal but built from different collinear segments (an edge crossing two
//! polygons' shared edge). `kernel/crossing.rs` now answers those by `same_lines` (four
//! input orientations) after the filter fails: 202.3 M (−26 %, ~2.3× i_overlay by
//! instructions; `compare_coord` 3 %). What is left is the noding (`XSweep::scan` 27 %,
//! `Found::test` 14 %). A double-double stage before the fallback was tried and made it
//! worse (283 M): the pairs are exactly equal, no finer filter can decide them. Wall
//! clock, load average 7.9–8.1, `BOOLEAN_ROWS=maps`, two runs: dissolve 1.35 ms (quiet,
//! before) → 1.12–1.21 ms, /i_overlay 2.98 → 2.48–2.49, /geo 2.78 → 2.30–2.31; the
//! jts×52 rows unchanged within noise (1.30–1.55 /i_overlay).
//!
//! Session 26, GEOS-837 dissolve, one thread, quiet machine (then a helper building on
//! the other core). The input: 494 rings, 2580 segments, of which ~650 run a side two
//! polygons share the other way; 1539 vertices and 2263 edges after noding, 800 vertices
//! of degree above 2, 18 components. Where a call's ~490 µs go (timers around the phases
//! of `traced`, 3001 calls): the noding 264 µs (54 %), the angular sorts and links 48,
//! the winding queries of the 18 components 37, the cycle walk 29, the boundary state
//! 21, the ring tracing and the output with the input's orientation ~72. Steady state
//! (3001 calls of one contender, `perf stat`): compgeom 0.50 ms, i_overlay 0.41, geo
//! 0.48; this table's single interleaved calls: 0.53, 0.44–0.45, 0.49 (1.07–1.08 × geo).
//! Called alone in a loop compgeom takes 36 minor page faults a call (glibc trims the
//! heap top it grew, 45 before the change below); in this table 0 (the earlier rows
//! leave a large heap). Kept: the boolean path takes each edge's first source and
//! winding changes straight from the noding's pieces (callgrind 5.298 → 5.252 M, wall
//! −2.8 %). Tried and not kept (wall, alternated runs): dropping the edges across which
//! no winding number changes before linking (+13 %: the components go from 18 to 39 and
//! the face around each must then be found); vertices kept as nearest points plus the
//! few crossings apart instead of 72-byte exact points (+3.6 % instructions); the
//! sweep's pair tests gathered over many entries into one loop (±0); the shared end
//! picked by selects instead of a four-way branch (±0); a shortcut of the winding
//! count by the segment's x range before the orientation (−0.7 % instructions, +1 %
//! wall); sorting networks on packed keys for vertices of degree 3 and 4 (+1.7 %
//! wall). The branchy code these replaced predicts well on this processor.
//!
//! Session 27, GEOS-837 dissolve. Kept: (1) segments whose contributions to the winding
//! numbers cancel (a side two polygons of one input share, run both ways) are left out
//! before the arrangement (`dcel/cancel.rs`; input of many short rings only, and not
//! with `keep_collinear`): 2580 → 1394 segments, 38 components instead of 18; steady
//! state (3001 calls, median of 7 alternated runs) 0.508 → 0.462 ms. Done inside the
//! noding instead (from the vertex hash's table of copies) it saved only 5–8%: the
//! winding counts of the components still ran over all 2580 input segments. (2) The face
//! around a component is looked for only where it is needed (components inside chosen
//! faces: 20 of the 38), by looking at every edge when there are at most 32 such queries
//! (`DIRECT_FACE_QUERIES`): 0.461 → 0.444 ms. The search over strips of all edges cost
//! 70–80 µs a call here (1556 edges), the winding counts 44 µs. Tried and not kept:
//! labels from the faces around every component instead of the winding counts (−7% on
//! the dissolve, which needs both, but +35% on the squares, whose 213 k edges make the
//! strips cost 19.6 ms against 0.7 ms for the counts, and +10% on the JTS pairs, which
//! need only the counts).
//!
//! Session 28. Squares (213 k edges at 1e4): (1) in the axis-parallel arrangement a cut
//! of a horizontal line takes its vertex from its contact, found by one forward walk
//! along the vertical line's cuts in the order the sweep lists the contacts, instead of
//! a galloping search over the vertical lines plus a binary search in one (two cache
//! misses a cut, 14% of the call): 0.96–1.01 → 0.86–0.87× geo. (2) When every edge is
//! axis-parallel, the outgoing half-edges of a vertex come in counter-clockwise order
//! from four slots per vertex instead of an angular sort that looked up every half-edge's
//! segment (20% of the call): −8%. (3) Edges stay in line order and vertices in the order
//! made (the order of the plane) instead of being renumbered along the input segments:
//! the records of one small face of many overlapping squares no longer lie far apart.
//! `examples/boolean_profile`: squares 1e4 about the same to −8%, 3e4 −15%, 1e5 −23%,
//! a 300 × 300 raster coverage (`cells`) −12%. (4) Fewer fresh pages: no narrower source
//! list copied into `Source`s, `Flat::summed` keeps one-source-per-edge sources, the
//! traced boolean reads the arrangement's sources and a byte per edge of axis direction
//! instead of a 16-byte record per edge: 1e5 squares 705 k → 533 k minor faults.
//! Dissolve: the direct face search (at most 32 queries) looks at each edge once against
//! the queries in its y range (sorted by y), not every edge per query: −5%.
//! Three full runs at the end (ratio compgeom / peer, i_overlay then geo): stars
//! 0.45–0.78 / 0.46–0.78; squares 0.74–0.85 / 0.71–0.73; water 0.63–0.83 / 0.60–0.80;
//! JTS×52 0.87–0.96 / 0.82–0.93; dissolve 1.02–1.04 / 0.92–0.93 (medians 0.93–0.95).
//! Growth of the squares, one call in a process of its own (`BOOLEAN_ONE`, `BOOLEAN_N`,
//! /usr/bin/time): at 1e5 (about 100× the edges of 1e4) user time 2.7–2.8 s against
//! geo's 3.1–3.2 s, but system time 1.4–3.2 s against 0.7 s, so wall 3.4–6.2 s against
//! 3.8–3.9 s (i_overlay 3.8–4.3 s). The system time is clearing fresh pages
//! (`clear_page_erms`, a third of the samples): 533 k faults against geo's 466 k, and on
//! this VM the cost of a fresh page varies two- to threefold between runs.
//!
//! Session 29, GEOS-837 dissolve: why the table's row (one call per contender per round)
//! is slower for compgeom than a loop of its calls. Three full runs: 0.43–0.44 ms
//! against geo's 0.42–0.44 (1.01–1.02 × geo, medians 0.99–1.00; session 28 measured
//! 0.92–0.93 on the same code). `BOOLEAN_ONE=<contenders> BOOLEAN_INPUT=dissolve`
//! ([`disturbed_rounds`], 1000 rounds, medians):
//!
//! | rounds of | compgeom | i_overlay | geo |
//! |---|---:|---:|---:|
//! | itself alone | 0.27–0.29 | 0.29–0.30 | 0.35 |
//! | ours,io,geo (the table's order) | 0.50–0.51 | 0.35–0.36 | 0.39–0.40 |
//! | the same, heap never trimmed (`GLIBC_TUNABLES=glibc.malloc.trim_threshold=100000000`) | 0.42–0.43 | 0.35 | 0.39–0.40 |
//! | ours,ours | 0.27 | | |
//! | alone, 300 k coin-toss branches before each call (`BOOLEAN_BRANCHY`) | 0.38 | 0.35–0.36 | 0.41 |
//! | alone, 64 MiB written before each call (`BOOLEAN_THRASH_KB`) | 0.35–0.37 | 0.35–0.36 | 0.43–0.44 |
//!
//! Two causes. (1) The heap: in this process glibc trims the heap top when compgeom's
//! temporaries are freed and grows it again in the next call (six `brk` a round, 40
//! page faults, all in compgeom's call); not in the table, whose earlier rows free
//! blocks large enough to raise the trim threshold (0 faults there, session 26), and it
//! costs ~0.08 ms here. (2) The branch predictor: a call repeated on the same input runs
//! with the predictor trained on that input, and compgeom's branchy exact code gains
//! most from it (+32–50% when anything else runs in between, against +10–20% for the
//! peers); a cold cache alone costs it little. Cachegrind's branch simulation (no
//! training across calls): 35.6 k mispredicts a call (4.0% of 890 k branches), spread
//! out: `traced` 7.9 k, the noding's sweep scan 2.5 k and pair tests 2.3 k, the
//! cancellation hash 2.0 k, the assembly 1.6 k, `Ends::of` 1.5 k, the rest under 1 k
//! each. Tried, not kept: `Point2 ==` without a branch per coordinate and the
//! cancellation's end order by a select (−1.5 k simulated mispredicts, no change in the
//! rounds: 0.426 against 0.426 ms). So the row is a tie with geo until a third or so of
//! those mispredicts go, and the table's single rounds are the fair figure here.
//! Later the same session the output became canonical (rings from their smallest
//! vertex, holes and polygons sorted: `overlay/trace.rs` `canonical_order`). On the
//! dissolve (46 polygons, 109 rings, 1189 vertices out) it costs a few µs directly, and
//! in a loop of calls a further 2–5% through the allocator (the output's order changes
//! which blocks the next call reuses; reversing the polygons alone costs 3%); in
//! alternated rounds with the peers the medians moved within noise (+0–2%). Two full
//! runs after it: dissolve 1.16–1.17 / 1.03–1.04 (medians 1.16 / 1.03–1.04); stars
//! 0.53–0.82 / 0.53–0.81, squares 0.62–0.65 / 0.68, water union 0.71–0.72 / 0.67–0.68,
//! JTS×52 0.93–0.94 / 0.91–0.93 (intersection and union rows).
//!
//! Session 30, GEOS-837 dissolve. The maps rows at the start: water 0.72–0.94 /
//! 0.66–0.91, JTS×52 0.94–0.95 / 0.90–0.95, dissolve 1.16 / 1.02 (0.44 ms against
//! 0.38 and 0.43). Is the cold cache part of the cost? Rounds of ours,io,geo with the
//! heap never trimmed (as in the table), medians: 0.420 / 0.348 / 0.390 ms; with 1 MiB
//! written before each call 0.424 / 0.348 / 0.391, with 4 MiB 0.426 / 0.354 / 0.396.
//! Alone: 0.280 ms, 0.281 with 1 MiB written before each call, 0.387 with 300 k
//! coin-toss branches. So cold data costs compgeom nothing measurable here (its ~1.1 MB
//! of temporaries a call, against i_overlay's 0.42 MB and geo's 0.54 MB by dhat, are
//! not what it waits for): the loss is the branch predictor (0.280 → 0.387) and, for the
//! rest, what the peers' code does to the predictor's tables and the instruction cache
//! (0.387 → 0.420; the hot code is some 60 KB: `traced` alone 27 KB, its closure 12 KB).
//! Shrinking the temporaries would not move this row; fewer unpredictable branches
//! would, and they are spread thin (cachegrind, per call: the winding and face searches'
//! y-range loops in `trace.rs` ~2.8 k, the noding's pair tests and sweep ~5 k, the
//! cancellation's hash ~1.5 k, the vertex classes ~1.3 k; no line above 1.2 k).
//!
//! Session 31: the results were not all valid, and now are (`overlay::rounding`: the
//! rounded result is checked, and the polygons where rounding may have broken it are
//! united again). The GEOS-837 dissolve timed above was invalid (a vertex rounded onto
//! the far side of a 200 m edge: edges crossing and overlapping; checked with
//! `validity_problems`), so its earlier figures were for a wrong answer. Most JTS×52
//! results (38 of 52 unions) and the water xor now fail the check too, mostly where a
//! vertex within a float gap of an edge ends up on its other side (whether each of
//! those was invalid was not checked; the XML suites' tests found them valid). All
//! these rows are now slower. Maps rows, one run (ratio compgeom / peer,
//! i_overlay then geo; earlier code in brackets, same run of the machine): water
//! intersection 0.84 / 0.77 (0.79 / 0.69), union 0.88 / 0.85 (0.92 / 0.78), difference
//! 0.82 / 0.85 (0.87 / 0.80), xor 1.02 / 0.97 (0.70 / 0.64); JTS×52 intersection 1.38 /
//! 1.35 (0.92 / 0.91), union 1.64 / 1.61 (0.96 / 0.93), difference 1.67 / 1.64 (0.94 /
//! 0.90), xor 3.03 / 2.93 (0.93 / 0.88); dissolve 1.75 / 1.59 (0.69 ms against 0.39 and
//! 0.43; was 1.16 / 1.04). Alone, the dissolve takes 0.62 ms (0.29): its result is one
//! large polygon, so uniting "only the polygons near a failing pair" is uniting nearly
//! all of it. Stars 1e3 0.92–1.10 / 0.87–1.05 (0.79–0.84 / 0.76–0.81: the check costs
//! ~15% at this size, and the xor is repaired); 1e4 and 1e5 0.57–0.85 / 0.57–0.92, the
//! squares 0.69 / 0.67 (no point moves on axis-parallel input: no check at all).
//! Tried and not kept: accepting a vertex that changed sides when it sits beside an end
//! of the edge (JTS union 1.64 → 1.42, the rest unchanged; weaker argument). What
//! would help: a repair local to the failing pair (re-node only the edges within reach
//! of it, keep the labels of everything else), instead of a union of whole polygons.
//!
//! Session 32: fewer repairs, a cheaper check (`overlay::rounding`). A pair failing on
//! a side flip now first moves its crossings to another float around their exact points
//! (one float away per axis at most) where that puts every near vertex on its side
//! (`nudge`), and a vertex exactly on an edge's line passes when only one of the three
//! points moved. Results still united again (`BOOLEAN_OP`, `BOOLEAN_INPUT=jts`): the
//! dissolve 0 (was 1), JTS×52 intersection 2, union 7, difference 4, xor 33 of 52
//! (xor was 48; its slivers thinner than a float gap collapse; counts after 9d839c5,
//! which moves nothing where three vertices of a ring round onto one point; the times
//! below are from before it, with difference 2 and xor 29). The check had also
//! started costing 10 ms on the star 1e5 intersection (a list of every edge: its fresh
//! pages), now gone. Full table, one run: stars 1e3 0.90–1.02 / 0.91–0.99, 1e4
//! 0.57–0.63 / 0.56–0.62, 1e5 0.66–0.74 / 0.62–0.70; squares 0.65 / 0.69; water
//! 0.80–0.95 / 0.78–0.93; JTS×52 intersection 1.29 / 1.28, union 1.42 / 1.41,
//! difference 1.45 / 1.42, xor 2.59 / 2.52; dissolve 1.46 / 1.31 (0.57 ms against 0.39
//! and 0.44). Rounds of ours, io, geo on the dissolve: 0.566 / 0.366 / 0.408 ms (1.55 /
//! 1.39; were 0.69 ms); alone 0.43 ms (0.59 at the start of the session, 0.29 before
//! session 31's check). Where the time goes now (perf, dissolve alone): the search
//! for near pairs (every point and every unmoved edge against a grid of the moved
//! items) about 60 µs, the rest of the check 20 µs. On the JTS xor the check's exact
//! sides of near pairs (`orient_exact` on crossings within a float gap: the Dyadic
//! fallback) and the 29 re-unions dominate. Not met: the JTS rows and the dissolve
//! (goal: within 1.5× of i_overlay and faster than geo).
//!
//! Session 33. Exact signs of constructed points now try double-double arithmetic with
//! an error bound before the big numbers (`kernel::crossing::decide`): every near-line
//! sign the `f64` filter left open in a test of 40 000 was decided there. JTS×52 (one
//! contender alone, 300 rounds): xor 2.95 → 2.64 ms, difference 1.48 → 1.32, union
//! 1.53 → 1.46. The check's near pairs of a small result are found by testing every
//! box pair (no grid) when that is at most 512 tests: `BOOLEAN_INPUT=ngons` (52 pairs
//! of regular k-gons, two crossings; µs per call, ours / i_overlay / geo) k = 4 3.1 →
//! 2.7 / 1.2 / 1.4, k = 50 9.0 / 7.4 / 7.8 (unchanged: the grid there). Tried and not
//! kept (no gain measured): the grid of moved items listing long edges only in the
//! cells along them (on the dissolve only 1 of 150 moved edges spans more than one row
//! and column: the moved items cluster, it is the per-point cost that counts, about 25
//! ns for each of 1 189 points and edges), a finer grid (2–4 cells per point: ±3%), a
//! sorted list instead of a hash set for the context's points. What the time is on the
//! JTS union now (perf): the noding 42%, the check 22% (its near-pair search 15%), the
//! tracing 14%, about 100 allocations a call against i_overlay's 23 and geo's 31 (a
//! counting allocator). Full table, one run after the session's changes: stars 1e3
//! 0.92–1.06 / 0.91–1.03, 1e4 0.50–0.64 / 0.57–0.62, 1e5 0.62–0.84 / 0.65–0.76;
//! squares 0.68 / 0.67; water 0.79–0.88 / 0.78–0.95; JTS×52 intersection 1.27 / 1.26,
//! union 1.35 / 1.31, difference 1.30 / 1.29, xor 2.29 / 2.24; dissolve 1.40 / 1.27
//! (0.55 ms against 0.39 and 0.43). Still not met: the JTS rows and the dissolve.
//!
//! Session 34. `BOOLEAN_ONE=pairs` (each JTS pair's best of 50 calls, µs, summed)
//! shows how far the JTS rows are from the goal when caches are warm: union 920 /
//! 535 / 572 (ours / i_overlay / geo), xor 1 707 / 563 / 616, intersection 655 / 430
//! / 456. With the rounding check switched off (an experiment, not kept): union 584
//! against geo's 516, xor 655 against 563. So the check (near pairs, exact sides,
//! nudges, re-unions) is about 29% of the union and 58% of the xor, and without it
//! compgeom is still 1.13–1.16× geo there: the goal needs both a cheaper check and a
//! cheaper pipeline for small inputs. Tiny pairs cost most relative to the peers
//! (pg-2055, 11 points: 26 µs against 0.5; geos-350, 10 points: 20–28 µs against 2):
//! 16–64 candidate combinations per failing pair in `nudge`, and exact zeros. Where
//! the time of the JTS xor's check went (instrumented, per round of 52): near pairs
//! 0.38 ms, first decisions 0.19, nudges 0.22, re-unions 0.50 (21 of 52 results
//! re-united). Of the pair decisions that failed in one xor round (nudge retries
//! counted), 51% were a point on the wrong side, 22% a point rounded onto the edge's
//! line, 27% a point exactly on the edge's line with two of the three points moved
//! (which no nudge changes unless it moves them apart). Changes: three points on the line of one
//! of their crossings' segments are collinear by orientations of input points
//! (`on_one_line`, 2 µs → tens of ns for such a zero), and a nudge saves the points
//! it may move once per pair. Maps rows, two alternating runs each of the session's
//! start and end: xor 2.26–2.32 → 2.16 / 2.20–2.25 → 2.08–2.09; the other rows within
//! ±2%. Full table, one run at the end: stars 1e3 0.93–1.06 / 0.91–1.03, 1e4
//! 0.53–0.68 / 0.55–0.66, 1e5 0.60–0.70 / 0.60–0.68; squares 0.66 / 0.69; water
//! 0.82–0.90 / 0.80–0.91 (0.96–1.07 / 0.96–1.07 when run alone, `BOOLEAN_ROWS=maps`);
//! JTS×52 intersection 1.24 / 1.24, union 1.37 / 1.35, difference 1.34 / 1.31, xor
//! 2.20 / 2.13; dissolve 1.39 / 1.27. Still not met: the JTS rows, the dissolve, and
//! (in most runs) the star xor at 1e3 against geo.
//!
//! Session 35. A pair whose point is beyond both ends of the edge in x or in y, where
//! rounding to nearest put them and where they end, passes the rounding check without
//! an exact test (monotone rounding keeps the exact points apart on that axis, and
//! straight moves keep them apart on the way: `apart_along_an_axis`). It decides most
//! crossings along one input edge. JTS results united again: intersection 2 → 1, union
//! 7 → 3, difference 4 → 3, xor 27 → 19 (6 → 5 of them twice). Per-pair best sums
//! (µs, 20 calls, two alternating runs of the session-start and new binaries): union
//! 795–800 → 735, xor 1 445 → 1 262–1 268, intersection 649–651 → 635, difference
//! 709–712 → 698–704; i_overlay 473 / 503 / 428 / 442, geo 510 / 556 / 457 / 480 in
//! the same runs. Nudging off (an experiment): union 863, xor 1 539, so nudges still pay. The JTS
//! xor decisions still failing after nudges: a moved point rounded onto another
//! vertex's point, or a wrong side that no float around the exact point mends without
//! breaking another pair; none on an exact collinear side now. Full table at the end
//! (three runs; the 1e4, 1e5 and squares rows one): stars 1e3 0.71–0.95 / 0.75–0.93 (xor 0.82–0.94 / 0.82–0.93), 1e4
//! 0.60–0.71 / 0.60–0.69, 1e5 0.61–0.77 / 0.65–0.80; squares 0.76 / 0.79; water
//! 0.75–0.98 / 0.76–1.00 (the xor 0.98 / 0.93–1.00; run alone with
//! `BOOLEAN_ROWS=maps` the water xor is 1.05–1.21 / 1.01–1.17 with either binary);
//! JTS×52 intersection 1.21–1.23 / 1.17–1.21, union 1.25–1.27 / 1.21–1.24, difference
//! 1.25–1.28 / 1.21–1.27, xor 1.85–1.94 / 1.79–1.88; dissolve 1.39–1.42 / 1.26–1.31.
//! In a water xor call, `near_pairs` is 13% (about 55 ns per point and edge queried)
//! and the faces left of the holes 19%.
//!
//! Later in session 35: `ring_orientation` sums the shoelace exactly as a float
//! expansion before falling back to big integers (re-united slivers far from the
//! origin; misc-2#0 xor 65 → 57 µs, the xor sum −2%), and a re-union checks only the
//! context polygons whose boxes come near its own (the xor sum 1 280 → 1 184 µs in
//! the same runs, pg-4538 xor 217 → 178 µs: building the set of every kept polygon's
//! points and querying them in `near_pairs` was most of a re-union on large results).
//! Sizing `traced`'s ring buffers to the edge count once (1–2% on the JTS sums) was
//! reverted: on the star xor at 1e3 it made each call take 74 page faults (0.14 →
//! 0.26 ms; `perf stat -e page-faults`), the allocator returning the larger heap to
//! the system after each call; capped at 1 024 it still did. Page faults per call
//! now: JTS xor 2, star 2, dissolve 6, water xor 829 (against about 550 for i_overlay
//! and 440 for geo, input loading included: a lever for the water rows). In a JTS xor
//! round, `near_pairs` sees 5 274 points, 958 moved edges and 507 moved points over 60
//! calls, about 23 ns per query, and is now 21% of the xor. Final table, two runs
//! (the machine slower and noisier than earlier in the session): stars 1e3 0.90–0.96
//! / 0.88–0.94, the xor 1.06–1.09 / 0.98–1.05; 1e4 0.56–0.72 / 0.54–0.84; 1e5
//! 0.59–0.87 / 0.58–0.81; squares 0.75–0.78 / 0.69–0.72; water 0.81–1.05 / 0.79–0.93
//! (the xor 0.96–1.05 / 0.87–0.93); JTS×52 intersection 1.21 / 1.20–1.22, union
//! 1.25–1.33 / 1.25–1.30, difference 1.30–1.32 / 1.23–1.28, xor 1.84–1.89 /
//! 1.77–1.82; dissolve 1.42 / 1.28. The star xor at 1e3 moves between 0.82 and 1.09
//! from run to run (the peers' times there vary by half).
//!
//! Session 36. The machine's speed varied by half within minutes, so changes were
//! measured by instructions (callgrind, `BOOLEAN_ONE=ours`, the inclusive count of
//! `boolean`, 5 calls) against the session-start binary: the rounding check's near
//! pairs by brute force up to 16 384 box tests (was 512) behind one test against the
//! box around all moved points, edges walked by a plain loop, unmoved edges' boxes
//! without the reach; foldhash for the re-unions' context points and the nudge's maps
//! (SipHash was 2% of the JTS xor); grid and strip cells through a conversion to u32
//! (to usize it took 16 instructions); each box's grid cells found once. JTS×52
//! intersection 62.5 M → 59.4 M (−4.9%), union 72.9 M → 68.6 M (−5.9%), difference
//! 68.0 M → 64.9 M (−4.7%), xor 112.6 M → 103.9 M (−7.8%); dissolve 28.3 M → 27.2 M
//! (−3.9%); water intersection −6.4%, union −5.0%, difference −5.7%, xor −7.2%
//! (`BOOLEAN_ONE` on the water and the stars now takes `BOOLEAN_OP`); stars 1e3
//! union −1.8%, xor −3.6%, 1e4 union −2.2%, xor −4.1%. Against the peers, per call
//! ((5 calls − 0 calls) / 5, the input's loading left out): JTS×52 intersection 11.9 M
//! against i_overlay 9.95 M and geo 10.2 M (1.20 / 1.17), union 13.8 M / 11.0 M / 11.3 M
//! (1.26 / 1.22), difference 13.0 M / 10.3 M / 10.7 M (1.26 / 1.22), xor 20.9 M /
//! 11.6 M / 12.2 M (1.80 / 1.70); dissolve 5.46 M / 4.00 M / 4.59 M (1.37 / 1.19);
//! water union 93.9 M / 97.0 M / 100.3 M, xor 133 M / 122 M / 130 M (ours counts the
//! rayon pool's threads: the noding's pair tests run on it from 16 k segments).
//! Tried and dropped (more instructions): one grid of all points and unmoved edges
//! queried by the moved items (dissolve near pairs 97 → 131–143 µs a call); a grid of
//! all points queried by the moved edges plus one of the moved points (water xor near
//! pairs 98 M → 105 M); the moved edges and the moved points on two separate grids
//! (96 M → 101 M: the grid of moved points, having fewer items, visits all of them for
//! long edges); box overlap tests without branches (callgrind counts more
//! instructions; not timed). Where the water xor's near-pair search goes: 34 k points,
//! 13 k moved edges and 8 k moved points a call, about 20 k pairs found, 32 M
//! instructions of 120 M (Grid set-up 4.7 M, visits 8.6 M with their callbacks). In
//! the JTS rows the noding is about half of the intersection (5.4 k segments a round,
//! 29 k candidate box tests, 9.8 k overlaps, 4.3 k of them consecutive ring edges
//! decided at once; about 215 instructions per exact pair test), allocation about 9%
//! (some 65 allocations a call).
//! A finite `gap` at `f64::MAX` (the near-pair search box around a point there held
//! its box again; found by a review, no effect on the timings). Final table, two runs
//! (ratios / i_overlay, / geo): stars 1e3 0.74–0.84 / 0.80–0.88; 1e4 0.50–0.72 /
//! 0.47–0.69; 1e5 0.62–0.71 / 0.56–0.69; squares 0.87–0.88 / 0.76–0.82; water
//! 0.83–0.99 / 0.77–0.95 except the xor 0.98–1.07 / 0.97–1.04; JTS×52 intersection
//! 1.23 / 1.16–1.22, union 1.23–1.24 / 1.21, difference 1.24–1.30 / 1.21–1.27, xor
//! 1.84–1.86 / 1.76–1.77; dissolve 1.32–1.34 / 1.23–1.24. Within the run-to-run noise
//! of the end of session 35 (the instruction counts fell 4–8%, the wall times on this
//! machine did not show it beyond its noise). Not met: the JTS rows, the dissolve, and
//! the water xor against geo in some runs.
//!
//! Session 37. Instructions as in session 36, against the session-start binary: the
//! tracing's ring buffers and the near pairs' lists sized once (JTS×52 intersection
//! −1.6%, xor −1.9%, then −0.4% and −0.9% more); the cancelling of shared sides on
//! the noding's hashed vertices (one hash of the ends for both, classes of equal
//! segments by vertex pairs, the noding's copies from those classes: two hashes of
//! points fewer). JTS×52 intersection 59.5 M → 58.2 M (−2.2%), union 68.7 M → 67.0 M
//! (−2.4%), difference 65.0 M → 63.6 M (−2.2%), xor 104.2 M → 100.5 M (−3.5%);
//! dissolve 27.2 M → 27.0 M (−0.9%), but in time, interleaved runs of 500 calls (8
//! each): best 0.301 s against 0.325 s, median 0.37 s against 0.43 s (the float
//! compares and mispredicted probes of the old cancelling went); water −0.1% to
//! −0.7%, stars unchanged. Per call against the peers ((5 − 0 calls) / 5): JTS×52
//! intersection 11.65 M (1.17 / 1.14), union 13.44 M (1.22 / 1.19), difference 12.75 M
//! (1.24 / 1.19), xor 20.19 M (1.74 / 1.65); dissolve 5.41 M (1.35 / 1.18).
//! `perf record` (cpu-clock sampling; the machine has no hardware counters) works here
//! and sees what callgrind does not: on the water xor about 8% of the samples are page
//! faults (the per-call arrays come from fresh pages each call); on the JTS
//! intersection malloc and free are about 10%, the sweep's scan 12% (its pair tests
//! mispredict), the tracing 15%. Tried and dropped: dropping the rings rounding leaves
//! fewer than three points (slivers within a float gap; a hole only when no point is
//! near it) instead of uniting again: JTS×52 xor re-unions 18 → 13, but nudging then
//! ran on 14 more results and cost more than the unions saved (+1.2%); the nudge's
//! failing pairs ordered by their nearest points before exact comparisons (no
//! change); the near-pair grid's queries on the rayon pool (the main thread's count
//! fell, but on 2 cores 100 water xor calls took 2.06 s against 1.87 s on one
//! thread); consecutive ring edges that turn left out of the sweep's branch-free box
//! loop (+4.5% instructions, no clear gain in time).
//! Final table, two runs (/ i_overlay, / geo): stars 1e3 0.75–0.94 / 0.79–0.95; 1e4
//! 0.48–0.88 / 0.48–0.92; 1e5 0.56–0.67 / 0.58–0.69; squares 0.75–0.82 / 0.78–0.80;
//! water intersection, union and difference 0.83–0.98 / 0.78–0.89, xor 0.96–1.01 /
//! 0.95; JTS×52 intersection 1.13–1.15 / 1.08–1.15, union 1.23 / 1.21–1.22,
//! difference 1.20–1.25 / 1.17–1.22, xor 1.74–1.78 / 1.67–1.70; dissolve 1.29–1.30 /
//! 1.18–1.20. Not met: the JTS rows and the dissolve.
//!
//! Session 38. Instructions as before, session-start binary against the end: the
//! rounding check's segment–box test by the box's two extreme corners (the side is
//! affine over the box) instead of four; a crossing's side of a float point per axis
//! from one double-double evaluation (`ExactPoint::compare_with_point`; two generic
//! comparisons before, each trying the `f64` filter, which never decides within a
//! float of the point); the noding's edge map, the nudge's maps and the re-union's
//! context points sized once, the nudge's candidates without intermediate vectors.
//! JTS×52 intersection 58.0 M → 57.5 M (−0.8%), union 66.6 M → 66.4 M (−0.3%),
//! difference 63.4 M → 62.4 M (−1.6%), xor 100.4 M → 98.1 M (−2.3%); dissolve −0.3%;
//! water −0.4% to −1.2%; stars unchanged. Per call against the peers: JTS×52
//! intersection 11.53 M, union 13.31 M, difference 12.52 M, xor 19.69 M (/ i_overlay
//! 1.70, / geo 1.61); dissolve 5.37 M (1.34 / 1.17). Where a JTS xor call goes now
//! (callgrind, the first pass of each pair): the noding about 6 M instructions, the
//! check about 5 M (near pairs 2.6 M, the nudge 0.6 M), the tracing itself about
//! 5.5 M, spread over many small steps; the re-unions 2.6 M (24 a call, most of a few
//! segments, but isochrone#4 and misc-2#0 unite their whole result again: 129 and 192
//! segments). About 142 allocations per pair (dhat), some 75 of them per `traced`
//! call, most once each: merging them would save a few percent at most. The failing
//! pairs the nudge leaves (one JTS xor round, 66): 24 are a point rounded onto an end
//! of the edge (the rings would touch there: only a union again decides that), 33 an
//! unmoved point on the wrong side of an edge with one or both ends moved, which no
//! float around those ends mends without breaking another pair. Table after the
//! changes above, three runs (/ i_overlay, / geo): stars 1e3 0.74–0.87 / 0.80–0.93;
//! 1e4 0.59–0.88 / 0.57–0.95 (one run's intersection 1.02 / 1.15, its instructions
//! unchanged: noise); 1e5 0.63–0.79 / 0.59–0.80; squares 0.78–0.82 / 0.75–0.79; water
//! intersection, union and difference 0.76–0.94 / 0.76–0.89, xor 0.90–0.99 /
//! 0.94–0.96; JTS×52 intersection 1.10–1.15 / 1.11–1.14, union 1.17–1.20 /
//! 1.14–1.17, difference 1.15–1.21 / 1.11–1.16, xor 1.72–1.75 / 1.64–1.66; dissolve
//! 1.27–1.30 / 1.18–1.19. Then the one-by-one near-pair search's box tests went
//! branch-free, 64 boxes into a mask at a time: instructions up (JTS xor +1.6%,
//! intersection +1.8%), time down (interleaved runs of 300 calls, 5–6 each, the best
//! and the median: JTS xor 684 / 688 ms against 700 / 712, intersection 381 / 396
//! against 395 / 406, union 436 / 438 against 445 / 449; the dissolve, which takes the
//! grid, the same). Final table, three runs: stars 1e3 0.71–0.85 / 0.77–0.87; 1e4
//! 0.43–0.87 / 0.46–0.90; 1e5 0.54–0.73 / 0.55–0.75; squares 0.81–0.92 / 0.79–0.84; water
//! intersection, union and difference 0.84–0.94 / 0.81–0.95, xor 0.98–1.12 /
//! 0.89–0.91 (the water xor's own time unchanged in interleaved runs: noise); JTS×52
//! intersection 1.09–1.18 / 1.05–1.17, union 1.12–1.22 / 1.13–1.19, difference
//! 1.13–1.15 / 1.11–1.15, xor 1.65–1.69 / 1.58–1.60; dissolve 1.25–1.30 / 1.14–1.20.
//! Not met: the JTS rows and the dissolve.
//!
//! Session 39. Instructions as before (inclusive `boolean`, 5 calls), session-start
//! binary against the end: an orientation with two of its points on one input segment
//! goes by that segment's line (`kernel::crossing`: degree 4, no homogeneous
//! coordinates; the rounding check's exact sides, 1 750 instructions each on the JTS
//! xor before); pairs of a point and an edge it is an end of left out where they are
//! found (rings touching at a vertex: about 3 000 a JTS xor round); the nudge moves one
//! vertex at a time (every mend on the JTS pairs moved one; a pair nothing mends cost up
//! to 64 tries, 183 k instructions a call on pg-2055's intersection); the one-by-one
//! near-pair search sorts 16 or more moved items into strips per axis as bit sets and
//! takes results up to 262 144 box tests (was 16 384). JTS×52 intersection 58.6 M →
//! 57.3 M (−2.1%), union 67.4 M → 65.9 M (−2.2%), difference 63.1 M → 60.6 M (−3.9%),
//! xor 99.7 M → 93.6 M (−6.1%); dissolve 26.7 M → 26.4 M (−1.1%); water intersection
//! +0.1%, xor −0.4%; stars 1e3 union −2.3%, xor −3.4%. The same re-unions on the JTS
//! pairs as before (1, 3, 3 and 19 results, 24 unions for the xor). Per call against the
//! peers: JTS×52 intersection 11.48 M (/ i_overlay 1.15, / geo 1.13), union 13.21 M
//! (1.21 / 1.17), difference 12.16 M (1.18 / 1.14), xor 18.79 M (1.62 / 1.54); dissolve
//! 5.30 M (1.32 / 1.16). Tried and dropped: `lto = "fat"` with one codegen unit (all
//! three contenders about 2% fewer instructions, the ratios the same); nudging where a
//! ring rounded to fewer than three points (its polygon is dropped; only three vertices
//! on one point make the merged ids depend on the numbering): xor −0.15%, the other rows
//! +0.2% to +0.8%; tracing rings from their lowest vertex so that merges are canonical
//! and nudging always (the same, about ±0); a sweep over the boxes' left sides instead
//! of the one-by-one search and the grid (xor +7%, water xor +32%: long moved edges
//! scan every point in their x-range); the one-by-one search's boxes side by side for
//! vectorized tests (the tests −35%, the search +9%: four more arrays per call); a look
//! at the grid cells before visiting each unmoved edge (dissolve +0.2%). Code layout
//! moves these counts by ±0.5% (splitting the near-pair search into two functions
//! changed which calls were inlined): differences below that are noise here. Where a
//! JTS xor call goes now: the noding 6.7 M instructions, the rounding check 4.7 M (near
//! pairs 2.6 M, the decisions 1.3 M, the nudge 1.1 M), the re-unions about 2.5 M
//! (misc-2#0, isochrone#4 and misc-4#1 unite most of their result again), the tracing
//! the rest. Table: see the closing note of the session.
//!
//! Session 40. A ring of a result that rounds to fewer than three points (a sliver
//! thinner than the rounding) is dropped without flagging its polygon, and no longer
//! keeps the check from nudging elsewhere in that result; only three vertices rounded
//! onto one point still do. Before, a dropped sliver hole sent its whole polygon to a
//! second union (misc-2#0's xor: 192 points, 0.53 M instructions a call), and any
//! dropped sliver left that result's mendable pairs to a union. Re-unions on the JTS
//! pairs: 1, 1, 1 and 14 results (was 1, 3, 3 and 19), 18 unions for the xor (was 24).
//! Instructions (inclusive `boolean`, 5 calls): JTS×52 xor 93.6 M → 90.3 M (−3.5%),
//! difference −0.4%, union −0.2%, intersection and dissolve ±0.05%, water the same.
//! Per call: JTS xor 18.13 M (/ i_overlay 1.56, / geo 1.48; was 1.62 / 1.54). Wall,
//! three interleaved runs of the maps rows: JTS xor / i_overlay 1.57–1.60 → 1.52–1.57.
//! What the xor's re-unions still cost: 1.6 M a call, isochrone#4 0.37 M of it (two
//! shells failing against each other: a union of 129 points), misc-4#1 0.29 M and
//! pg-4538#0 0.27 M (two rounds each). Of a small re-union's cost, the context (the
//! kept polygons near it: their points in the check, and the second round when one of
//! them fails) is more than half: pg-4538#0 0.27 M → 0.10 M with none (not a valid
//! change, a measure). A review then found a bug older than this change: an island
//! inside a hole that rounds away overlapped the hole's polygon; both are now united
//! again (no change in the counts above: no JTS result has one). The dissolve's +1.3%
//! after unrelated edits was the rounding grid's `visit` and `may_meet` becoming calls
//! (5 000 a call): both are now always inlined. With that, `orient_along` answering
//! collinear at once for a third point on the segment by construction: intersection
//! −0.3%, xor −0.25%, dissolve ±0. Session start to end: JTS×52 intersection 57.30 M →
//! 57.13 M (−0.3%), union ±0, difference −0.5%, xor 93.56 M → 90.20 M (−3.6%),
//! dissolve +0.2%, water +0.1%. Per call: intersection 11.45 M (/ i_overlay 1.15, /
//! geo 1.13), union 13.20 M (1.21 / 1.17), difference 12.10 M (1.17 / 1.13), xor
//! 18.11 M (1.56 / 1.48), dissolve 5.31 M (1.32 / 1.16). Then the near-pair searches'
//! box walks always inlined with their callbacks (25 000 calls a JTS xor run before):
//! xor −0.37%, the other JTS rows −0.2%, dissolve, water and stars ±0. Tried and
//! dropped: `reach_of`, `edge_reach` and `point_box` always inlined (intersection
//! +0.2%, xor +0.5%); `#[inline]` on the noding's union–find `union` (no change); a
//! second nudge, of a point of the one pair a first nudge
//! broke (xor +3.4%, the other rows +0.7% to +1.2%: collecting the pairs around every
//! failing pair's points costs more than the unions it saves). Where the xor's check
//! goes (5.0 M a call over 58 checks of about 87 points each): the near-pair search
//! 2.5 M, spread over per-point box work with no single hot spot, the nudge 1.6 M
//! (its O(points) set-up in every result with a failing pair, and the exact tests of
//! its candidates), the decisions the rest. Full table at the end of the session
//! (/ i_overlay, / geo): stars 0.55–0.85 / 0.55–0.86, squares 0.77 / 0.74, water
//! 0.86–0.98 / 0.80–0.90, JTS×52 intersection 1.11 / 1.10, union 1.11 / 1.10,
//! difference 1.13 / 1.07, xor 1.54 / 1.46, dissolve 1.28 / 1.18.
//!
//! Session 41. Wall time on the large inputs turned out to be lost to page faults,
//! which callgrind does not see: 40 water intersections took 0.57 s with glibc's
//! defaults and 0.49 s with its trimming and mmap thresholds raised out of reach
//! (`GLIBC_TUNABLES`), 42 957 minor faults against 3 434, about 2 µs a fault on this
//! machine; the peers barely moved. glibc returns the top of the heap beyond about
//! twice the largest block freed so far, so an overlay whose peak exceeds that pays a
//! fault for every page above it, every call. Page faults for 20 water calls
//! (`/usr/bin/time`, ours at the session start → end; i_overlay): intersection
//! 23 067 → 4 461 (9 328), union 7 209 → 4 165 (11 267), difference 23 166 → 4 837
//! (9 600), xor 29 456 → 17 037 (13 132). What did it: the arrangement's vertices
//! stored compactly (an input vertex 20 bytes instead of 88: the largest array of the
//! overlay, alive through the tracing and the check), the grid search's list of
//! unmoved edges as their ends only, sized once. Freeing the tracing's arrays before
//! the check, tried too, lowered the peak but made glibc trim in the middle of the
//! call: union faults 4 166 → 35 179, dropped. The instructions moved little: the
//! grid search visiting the cells of the rough box and making the precise box only
//! for edges there (water intersection −0.6%, dissolve −0.9%), a point's own edges
//! set aside before its precise box (JTS rows −0.6%, water xor −2.2%), the output
//! sorted by integer keys of the shells' lowest points (water xor −1.0%). Session
//! start to end (inclusive `boolean`, 5 calls): JTS×52 intersection 57.03 M → 56.68 M
//! (−0.6%), union 65.71 M → 65.11 M (−0.9%), difference 60.23 M → 59.96 M (−0.4%),
//! xor 89.94 M → 89.01 M (−1.0%); water intersection −2.1%, xor −3.3%; dissolve
//! 26.45 M → 26.10 M (−1.3%). Wall, the maps rows of two interleaved runs, start → end
//! (/ geo): water intersection 0.86–0.97 → 0.73–0.82, union 0.98–1.01 → 0.80–0.83,
//! difference 1.02–1.08 → 0.73–0.74, xor 1.14–1.24 → 1.01–1.02 (all four water rows
//! had crept over geo on this machine). Tried and dropped: the near-pair search on
//! small results as scans of every point against each moved edge and every edge
//! against each moved point, 64 box tests at a time (intersection +2.5%, xor +7.6%
//! with up to 8 192 tests a result; ±0.7% with up to 1 024); the search from the
//! moved items on a grid of all points and edges (intersection +6.6%, xor +16%: a
//! moved edge's box holds many points, each needing its precise box); one and eight
//! grid cells per moved item instead of about two (water xor +1.5% and +5%). Per JTS
//! pair (`BOOLEAN_ONE=pairs`, intersection, µs, ours / geo): pg-4538#0 92 / 67 (685
//! points, many a few floats apart), pg-2055#0 17 / 0.9 (a spike of a hole: 8 of the
//! 13 near pairs of its 7-point result fail and the nudge tries them all), misc-2#1
//! 18 / 5.4 and misc-2#0 22 / 11: these four are more than the row's whole gap to geo
//! (740 against 679 µs summed); pg-list#1 36 / 108 and misc-4#1 31 / 41 go the other
//! way. Full table at the
//! end: stars 0.54–0.83 / 0.53–0.83, squares 0.76 / 0.75, water 0.77–0.87 / 0.70–0.85,
//! JTS×52 intersection 1.13 / 1.11, union 1.14 / 1.14, difference 1.13 / 1.07, xor
//! 1.54 / 1.46, dissolve 1.23 / 1.15.
//!
//! Session 42. Where the JTS rows lose: per pair, geo's instruction counts are within
//! 1–3% of i_overlay's (it runs i_overlay), so faster than geo means within a few
//! percent of i_overlay. Per call on the 52 intersections (callgrind, per pair): ours
//! 11.36 M, i_overlay 9.95 M, geo 10.18 M. A call on two squares (`BOOLEAN_INPUT=ngons
//! BOOLEAN_K=4`) costs 38 k instructions against i_overlay's 22 k, 27% of it malloc
//! and free (75 blocks a call; glibc's free took 88 instructions on average here):
//! that fixed excess, 16 k over 52 calls, is most of the row's gap (about 0.8 M of
//! 1.2 M). The rest is in few pairs: pg-2055#0 219 k against 13 k (its nudge 97 k),
//! misc-2#0 342 k / 158 k, misc-2#1 258 k / 86 k; pg-4538#0 1 543 k / 1 066 k has no
//! pathology (2 250 instructions a point against 1 550). The xor's extra over the
//! intersection is mostly the rounding check (failing_rings 27% of the xor): at each
//! crossing four result edges meet, and the far end of each is near the other ring's
//! edges there (1 274 near pairs for the 52 results against 233). Changed: `orient2d`
//! evaluates in plain `f64` with Shewchuk's first bound before its range check and
//! `robust` (the orientations took half the instructions); up to 24 segments the
//! noding tests every pair's boxes without building the sweep (two squares 38.4 k →
//! 35.6 k instructions a call); the rounding grid scales coordinates by a power of two
//! where an extent's side overflows or is subnormal, and spans the finite box ends only
//! (stars of 5 000 vertices at 8e307 or 5e-318: 490 s → 19 s, against 15 s at scale 1).
//! Session start to end (inclusive `boolean`, 5 calls): JTS×52 intersection 56.68 M →
//! 55.49 M (−2.1%), union 65.12 M → 63.95 M (−1.8%), difference 59.98 M → 58.69 M
//! (−2.2%), xor 89.01 M → 86.52 M (−2.8%); water intersection −0.1%, xor −0.5%;
//! dissolve 26.09 M → 25.61 M (−1.8%). Tried and dropped: strips from 3 looked-at
//! pairs per segment instead of 8 (JTS intersection +4.6%); the sweep's box tests into
//! a bit mask (+0.6%); every pair up to 40 or 64 segments (+0.2%, +1.2% against 24);
//! the nudge's order of failing pairs compared by rounded points first (xor −0.1%);
//! the bench's counting allocator forwarding zeroed allocations to `calloc` (ours
//! +1.2% instructions, wall the same). Not done: a per-thread pool of the tracing's
//! temporary arrays (about 40% of the blocks; mimalloc, all blocks, was −4%). Two full
//! tables at the end (/ i_overlay, / geo): stars 0.49–0.79 / 0.52–0.85, squares
//! 0.72–0.75 / 0.64–0.72, water 0.68–0.91 / 0.67–0.90, JTS×52 intersection 1.09–1.10 /
//! 1.06–1.08, union 1.09–1.13 / 1.06–1.08, difference 1.11–1.12 / 1.06, xor 1.50–1.52
//! / 1.43, dissolve 1.21–1.22 / 1.12–1.14.
//!
//! Session 43. Two changes. (1) The boolean path's temporary arrays come from a
//! per-thread pool (`compgeom::scratch`: at most 16 arrays of up to 64 KiB per element
//! type are kept): on the JTS pairs 79 → 47 allocations a call; 98% of the pool's takes
//! find an array large enough, because a call takes and hands back its arrays in the
//! same order each time. Taking the nudge's arrays from it too broke that order (+0.9%
//! on the JTS xor), and so did a fallback search for a larger kept array (+0.4%): both
//! dropped. (2) The rounding check's near-pair search on the grid first asks a bitmap
//! of the moved items' boxes, widened by twice the rough box of a point (so a point is
//! looked up by its centre's cell), whether a point or edge can be near any; it is made
//! only where there is at most one moved item per four points (water's results have
//! one per two, half their points near one: a sieve there cost +3%, and a sieve
//! dropped after 512 queries that kept a quarter still +0.5%). The moved edges now come
//! from the moved points (O(moved + rings), not a walk over every edge), and the
//! unmoved edges are walked without a list. Star 1e4 xor: 24 moved items among 40 000
//! queries; the search went from 5.96 M to 4.12 M instructions a call with the sieve
//! and to 2.64 M with both. Session start to end (inclusive `boolean`, 5 calls):
//! JTS×52 intersection 55.52 M → 53.52 M (−3.6%), union 64.03 M → 60.46 M (−5.6%),
//! difference 58.74 M → 56.29 M (−4.2%), xor 86.62 M → 82.16 M (−5.2%); dissolve
//! 25.65 M → 24.43 M (−4.7%); water intersection 451.99 M → 442.72 M (−2.1%), xor
//! 564.63 M → 550.83 M (−2.4%); stars 1e3 union −3.4%, xor −5.3%; stars 1e4 union
//! −4.1%, xor −10%; squares 1e4 −1.5%. Also tried: a grid of 8 cells per item instead
//! of 2 for the near-pair search (dissolve −0.4%, water xor +5%). Review follow-ups:
//! the sieve's columns and rows come from the ratio of its sides (near 1e306 both
//! products with the count overflowed: 256 n² cells, 288 MB for 1 000 moved points);
//! zero-filled arrays too large for the pool come from `vec!` again (zeroed pages, no
//! write pass: squares 1e4 −1.6%, dissolve −0.8%). Three full tables at the end,
//! alternating with the session's starting build (/ i_overlay, / geo; start in
//! brackets): JTS×52 intersection 1.02 / 1.00–1.02 (1.06–1.09 / 1.07), union 1.01–1.06
//! / 0.99–1.01 (1.09–1.14 / 1.08–1.09), difference 1.02–1.06 / 1.01–1.02 (1.08–1.11 /
//! 1.06–1.07), xor 1.38–1.41 / 1.32–1.34 (1.47–1.50 / 1.40–1.43); dissolve 1.16–1.21 /
//! 1.06–1.11 (1.22–1.24 / 1.12–1.16); water 0.69–0.94 / 0.69–0.90 (0.69–0.97 /
//! 0.69–0.92); squares 0.69–0.78 / 0.73–0.84 (0.69–0.76 / 0.66–0.73); stars 1e3
//! 0.64–0.79 / 0.65–0.79 (0.71–0.81 / 0.75–0.85), 1e4 0.51–0.59 / 0.51–0.56 (0.55–0.67
//! / 0.52–0.71), 1e5 0.50–0.68 / 0.48–0.64 (0.57–0.65 / 0.56–0.65).
//!
//! Session 44. Where the JTS xor's excess over its union is (callgrind, 5 rounds): the
//! rounding check 20.7 M against 7.8 M (near-pair search 9.6 M, nudge 7.1 M), and the
//! 18 re-unions a round (6.1 M); the near-pair search is 2.1 M of set-up (boxes, strips),
//! 5.3 M of point queries against the moved edges (about 2 000 queries a round past the
//! box around all moved edges, 70% of them with a box hit: the work is real, not the
//! filter) and 2.3 M of unmoved edges against the moved points. Of 140 failing pairs a
//! round, 36 stay failing after the nudge: mostly a crossing standing at two points (the
//! xor's pinch vertices) whose every candidate float breaks another pair at its other
//! point. The nudge now keeps its places and the pairs at their points in sorted arrays
//! (no hash maps, no per-point tables over every point), its candidate points in a fixed
//! array, and orders the failing pairs on their rounded points where those differ: the
//! same results on all 52 pairs and four operations (compared bit for bit), nudge 7.06 M
//! → 6.91 M. For the dissolve: `ring_orientation`'s filter pairs each vertex with the
//! one before in a plain loop and looks for non-finite coordinates only where it fails
//! (−1.2%); the list of segments left after cancelling gets its room once (−0.3%); the
//! hole search with few queries skips edges above or below every query (−0.4%).
//! Session start to end (inclusive `boolean` or `union_all`, 5 calls): JTS×52
//! intersection 53.45 M → 53.32 M (−0.2%), union 60.36 M → 60.09 M (−0.4%), difference
//! 56.22 M → 55.92 M (−0.5%), xor 82.07 M → 81.70 M (−0.5%); dissolve 24.24 M → 23.70 M
//! (−2.2%); squares 1e4 214.01 M → 213.08 M (−0.4%); water and stars within ±0.05%.
//! Wall time moved within this machine's noise that day (three alternated tables: the
//! JTS rows 1.0–1.1 against geo at both ends, xor 1.29–1.41, dissolve 1.07–1.10 against
//! 1.06–1.25). Tried and dropped: a tighter ring-to-segments
//! loop (one pass of known length, zero-length segments taken out after): JTS −0.2%,
//! dissolve +0.5% (its rings are short); `codegen-units = 1` for the release profile:
//! ours −2.0% / −1.6% / −0.8% instructions on the JTS intersection, xor and dissolve,
//! geo's −1.1% / −1.2% / −1.0%, i_overlay's −1.0% / −0.9% / +0.6%, release builds twice
//! as long; fat LTO on top changed nothing more.
//!
//! Session 45. What the answers are worth: the JTS pairs' results of all three are now
//! checked with `validity_problems` (OGC rules, ring orientation aside; the check itself
//! agrees with JTS on the 136 polygonal isValid cases of the JTS and GEOS suites):
//! i_overlay's union is not valid for 3 of the 52 pairs, its difference for 2, its xor
//! for 6 (rings touching themselves), and its dissolve is not valid; geo's (which post-
//! processes i_overlay's) and ours are all valid. Where the JTS rows' cost goes, against
//! i_overlay, callgrind, 5 rounds of the intersection: i_overlay's whole call 49.6 M, of
//! it its noding (`split`) 29.2 M; ours 53.3 M, of it the noding 28.4 M, the rounding
//! check 5.9 M and the tracing about 17.5 M. The noding is not where the gap is: the
//! check is the price of valid output, and the tracing's passes are flat (no line over
//! 1% of the call). On the xor the whole excess over geo (16.4 M against 12.2 M a round)
//! is the check (4.1 M a round against 1.6 M for the union) and the re-unions (1.2 M).
//! Tried and dropped: finding the points near each moved edge from the points sorted by
//! x (binary search, then a walk over the edge's x-range) instead of each point against
//! the moved edges' boxes: intersection 10.69 M → 10.85 M, xor 16.42 M → 17.26 M a round
//! (the sort costs more than the queries it saves on results of ~100 points).
//!
//! Session 47 (no change to the boolean path; these are what was measured and tried).
//! Which JTS pairs lose: per pair (`BOOLEAN_ONE=pairs`, intersection, µs, ours /
//! i_overlay / geo; sums 689.5 / 646.0 / 675.1) the isochrone pairs where one polygon
//! lies inside the other and they share long stretches of boundary (#9, #12, #16, #19,
//! #23, #30, #31: 1.5–2.4× geo) lose, those that overlap in part (#0, #2, #4, #20, #27,
//! #29: 0.8–0.95×) win. The peers' cost follows the crossings, ours the segments: per
//! call (callgrind) isochrone#9 (89 segments, few crossings) ours 156 k, i_overlay 75 k,
//! geo 79 k; isochrone#27 (105 segments, many crossings) ours 182 k, i_overlay 195 k,
//! geo 200 k. Of ours on #9: noding 89 k (candidate search 37 k for 373 box-overlapping
//! pairs, crossing tests 14 k for 111 of them, assembly 30 k), the rounding check 13 k,
//! the tracing about 40 k in `traced` itself: no piece is the gap, each is ~2× what the
//! peers spend per segment. The near-pair search of the check, per round of the JTS
//! intersection (52 calls, 1 858 points, 256 moved, 473 moved edges): setup 0.19 M, the
//! points against the moved edges 0.38 M (~200 instructions a point), the unmoved edges
//! against the moved points 0.22 M. On the xor, of 1 274 near pairs a round 140 fail
//! before the nudge and 36 after it (in 18 results, which are united again); of the 36,
//! most are a vertex of a sliver ring of three or four points turned over by rounding.
//! Tried and dropped: (1) deciding a failing pair with one moved point by its actual
//! path (the moving vertex's segment against the edge, or the triangle a moving end
//! sweeps against the vertex, exactly) instead of the side test: of the 140 failing
//! pairs it applies to 73, and not one of them passed (they are real crossings of the
//! rounded rings); the exact tests cost +3% (16.52 M → 17.04 M a round); (2) the near-pair search transposed for
//! small results (each moved item's box against all points' or edges' boxes, 64 at a
//! time, pairs sorted after): intersection 10.71 M → 10.89 M, xor 16.52 M → 17.39 M (the
//! per-point union-box test of the present search skips a third of the points, the
//! transposed one tests them all); (3) dropping a turned-over triangle (exact area of
//! the wrong sign) instead of uniting its polygon again: would spare 3 of the 18
//! re-unions a round, not taken.
//!
//! Page faults (session 47, `perf stat -e page-faults`, consecutive calls of one
//! contender, `BOOLEAN_ONE`): ours took 11 540 page faults for 400 dissolves (i_overlay
//! 282, geo 316) and 19 970 for 20 unions of the 10⁴-vertex stars: arrays above 64 KiB
//! were freed at the end of each call, glibc trimmed the top of the heap and the next call
//! faulted the pages back. With the scratch pool keeping arrays up to 1 MiB (2 MiB of them
//! per thread): 480 and 2 550 page faults, 250 → 200 ms (geo 210, i_overlay 184) and
//! 84.5 → 50.4 ms (i_overlay 100, geo 103). The table's alternating single calls did not
//! move (the peers' calls in between leave the heap grown), hence the "in a row" column;
//! in the full table the dissolve in a row stays 1.19 / 1.08 (0.59 ms; alone 0.50: in
//! that process the earlier rows have raised glibc's trim threshold already, and what is
//! left is presumably session 29's second cause, the branch predictor trained on other
//! code; not measured again). This
//! is session 29's first cause (the heap), now gone for calls alone. Full table
//! after the change (machine shared with a fuzzer on one core), ratio to i_overlay / geo,
//! alternating (in a row): stars 1e3 0.70–0.80 / 0.76–0.84 (0.64–0.90 / 0.66–0.89), 1e4
//! 0.49–0.58 / 0.48–0.57 (0.49–0.57 / 0.50–0.54), 1e5 0.52–0.60 / 0.46–0.60 (0.51–0.53 /
//! 0.48–0.50); squares 0.75 / 0.69 (0.69 / 0.63); water 0.83–0.94 / 0.75–0.87 (0.73–0.92
//! / 0.67–0.83); JTS intersection 1.03 / 1.01 (1.04 / 0.99), union 1.02 / 1.02 (1.08 /
//! 1.02), difference 1.01 / 1.01 (1.05 / 1.01), xor 1.41 / 1.33 (1.45 / 1.36); dissolve
//! 1.19 / 1.11 (1.19 / 1.08).
//!
//! Session 48: results are now minimal in floats too (the points rounding left straight
//! between their neighbours are dropped, `overlay::rounding::straight`). Its cost, per
//! round (callgrind, the pass switched off in the same build for the baseline): JTS
//! intersection 10.755 M → 10.838 M (+0.8%), xor 16.538 M → 16.827 M (+1.7%), two
//! squares ×52 1.766 M → 1.779 M (+0.8%, ~250 instructions a call): each output point
//! next to a moved one is tested for lying between its neighbours, and in a xor almost
//! every point is. (Tried: the exact `orient2d` behind a float filter, no change: the
//! scan itself is the cost; the scan over array windows instead of indices saved a
//! third of it.) Two more fixes after an independent review: polygons near a ring
//! whose three vertices rounded onto one point are united again with it (a chord
//! rounded over a neighbour's corner had left crossing edges), and after a repair the
//! final set is looked over once for a point a settled polygon kept for a ring that
//! the repair's union no longer has (counting the points' uses only when some point is
//! straight: counted always, the JTS xor paid +2%). After both: JTS intersection
//! 10.840 M, xor 16.920 M a round (against 10.755 M / 16.538 M before the session:
//! +0.8% / +2.3%). Full table after the first change (a review's builds beside it, load
//! 1.4–2), ratio to i_overlay / geo, alternating (in a row): stars 0.45–0.81 / 0.47–0.81
//! (all in a row ≤ 0.80); squares 0.77 / 0.84 (0.86 / 0.88); water 0.73–0.92 / 0.66–0.93
//! (0.72–0.93 / 0.71–0.86); JTS intersection 1.04 / 1.04 (1.04 / 1.00), union 1.09 /
//! 1.06 (1.11 / 1.07), difference 1.07 / 1.01 (1.08 / 1.04), xor 1.47 / 1.40 (1.47 /
//! 1.37); dissolve 1.20 / 1.11 (1.18 / 1.07). Validity: ours 0 invalid everywhere,
//! i_overlay 3 / 2 / 6 invalid on the JTS union / difference / xor and its dissolve
//! invalid, as before.
//!
//! Session 49: no change to the boolean path's speed; where the JTS xor's excess comes
//! from, measured (a throwaway build counting per call; callgrind per round of 52). The
//! xor's results have 5 045 points (intersection 1 858, union 3 911), 500 of them moved
//! (256, 254), 1 274 near pairs (233, 329), 140 failing before the nudge and 36 after
//! (22 → 4, 30 → 2), and 18 results united again, 366 points in all (1 and 1): the xor
//! keeps every sliver between near-coincident edges of A and B, which the JTS pairs are
//! made of, and slivers are where rounding breaks things. Per round the check costs the
//! xor 4.08 M instructions (near pairs 1.92 M, first decisions 0.75 M, about 590 a pair,
//! the nudge 1.38 M) and its re-unions 1.2 M, of 16.9 M (geo 12.2 M): without any of it
//! the xor would be at 11.6 M, below geo, so the rest of the pipeline is not what keeps
//! this row above 1; only a check that costs a tenth of this one would. The intersection
//! (10.84 M against geo's 10.19 M), union (12.32 M / 11.28 M) and difference (11.28 M /
//! 10.67 M) are 6–9% above geo in instructions, most of it the cost of a small call:
//! two squares cost 33.9 k instructions a call against geo's 24.1 k (the noding 13 k,
//! the check 3.6 k, 23 allocations about 3.5 k, the scratch arrays about 4 k), and the
//! 52 calls' share of that difference is 0.49 M of the intersection's 0.65 M. Per pair,
//! warm (`BOOLEAN_ONE=pairs`, best of 50 calls, µs, summed over the 52 pairs): xor 1 139
//! against i_overlay's 752 and geo's 821; the largest excesses pg-4538 (685 points) 158
//! against 96, misc-4#1 81 against 53, isochrone#4 49 against 23, pg-2055 (11 points,
//! a degenerate hole) 17 against 1.2. (`BOOLEAN_ONE=pairs` took a single cold call per
//! pair unless `BOOLEAN_REPS` was set, which made small pairs look 10× slower; it now
//! takes 50.) Table, load about 2.5 (a test run had just ended), ratio to i_overlay /
//! geo, alternating (in a row): stars 0.53–0.82 / 0.50–0.81; squares 0.76 / 0.67 (0.70 /
//! 0.67); water 0.72–0.93 / 0.72–0.94 (0.73–0.97 / 0.68–0.89); JTS intersection 1.04 /
//! 1.03 (1.06 / 1.02), union 1.08 / 1.08 (1.09 / 1.06), difference 1.06 / 1.00 (1.07 /
//! 1.03), xor 1.47 / 1.41 (1.52 / 1.43); dissolve 1.21 / 1.08 (1.14 / 1.05). Validity
//! as before.
//!
//! Session 50. A new row, `turned square union`: the 10⁴ squares turned by random
//! angles, so that their crossings are constructed points and the rounding check runs on
//! a dense arrangement (0.50–0.69 against both peers). It found nothing at 10⁴, but the
//! same kind of input at higher density did: the check's grid (`rounding::grid`) met
//! every item over 64 cells at every query, and on dense results cells are small (an
//! overlay of 2 × 10⁴ turned squares: 26 706 such items, 1.6 M queries; more than 140 s).
//! Items over more cells are now listed in them too while the entries stay within 16
//! per item (2 × 10⁴ turned squares: 6 per item), the largest wide past that; items
//! over at most 64 cells are listed as before: that overlay 4.8 s, `compgeom boolean union`
//! of 4 × 10⁴ turned squares 1.51 → 0.96 s, outputs byte-identical; the table's rows
//! are unchanged (GEOS-837 dissolve 4.770 M → 4.758 M instructions). At 3 × 10⁴ turned
//! squares (`BOOLEAN_INPUT=turned BOOLEAN_N=30000`, one call, with the input's set-up
//! for all three) compgeom executes 3.88 G instructions against i_overlay's 8.36 G but
//! takes 1.09 s against 0.92 s (346 MB against 267 MB): dense arrangements are memory
//! bound, a profile puts 15% of the time in the angular sort's direction lookups (the
//! half-edge's source, then its segment, both random). Tried and dropped: a per-edge
//! array of those directions, made only from 2¹⁵ edges on, cost the JTS intersection
//! +0.7–1.5% instructions however it was written (code generation of `traced`); the
//! point sieve on the one-by-one near-pair search, +0.4% (intersection) and +0.7% (xor);
//! fat LTO with one codegen unit, −1.3% instructions for all three contenders alike.
//! Table (a review's builds beside it, load about 4), ratio to i_overlay / geo,
//! alternating (in a row): stars 0.44–0.82 / 0.45–0.81; squares 0.64 / 0.63; turned
//! squares 0.50 / 0.50 (0.61 / 0.77); water 0.71–1.01 / 0.77–0.96; JTS intersection
//! 1.03 / 1.02 (1.05 / 1.04), union 1.07 / 1.08 (1.08 / 1.05), difference 1.06 / 1.00
//! (1.05 / 1.02), xor 1.43 / 1.35 (1.46 / 1.39); dissolve 1.22 / 1.13 (1.20 / 1.08).
//!
//! Session 51: how cost grows with n at constant density (`BOOLEAN_SPREAD=1`: the
//! squares over a square of side sqrt(n / 10⁴); one call, its own time on stderr, s,
//! compgeom / i_overlay / geo). Turned squares at the session's start: 10⁵ 0.95 / 1.39
//! / 1.32 (process times), 10⁶ 28.0 / 15.6 / 16.7: ours grew 22× for 10× n, the peers
//! 11×. A profile: a third of the time the kernel clearing freshly faulted pages, a
//! quarter the tracing's walks around faces (`next`, `cyc`: a cache and TLB miss per
//! step), because the arrangement numbers edges in the order of the segments and the
//! squares came in random order; the same squares listed in Z-order took 13.4 s. The
//! boolean operations now put the polygons of a large input (64 polygons and 2¹⁴
//! points or more) in Z-order themselves (`overlay::locality`): 10⁶ turned squares
//! 14.6–17.9 s (noisy: page faults cost 4–8 s of system time from run to run), the
//! 10⁴ turned squares row 61.6 → 51.5 ms. That reorder made the GEOS-837 dissolve 66%
//! dearer through a bad sample (its rings are hashed into vertices only when a sample
//! of 32 segments shows short rings; 2 of 32 were ring starts in the new order against
//! 18% of all segments): ring starts are now counted in full (JTS rows and dissolve
//! within ±0.4% instructions), and inputs below 2¹⁴ points keep their order. Axis-
//! parallel squares, 10⁵: 0.60 / 0.50 / 0.49; 10⁶: 15.4–17.9 / 5.7–6.0 (user time
//! 10.1 s, peak 3.42 GB against i_overlay's 2.32 GB): a seventh of the samples were
//! the sweep's binary searches over 2 × 10⁶ horizontal keys (cache misses); searched
//! through a sample of every 64th key now, 12.7 s (user 8.3 s). Still 2.2× i_overlay
//! there, and 1.2× at 10⁵: memory (page faults) and the tracing's walks, which follow
//! the lines' order (horizontals by y, verticals by x) rather than the plane's. The
//! parallel noding's parts are now joined once (2.00 M → 1.91 M page faults at 10⁶
//! turned squares). Later in the session, on a quiet machine (call s, compgeom /
//! i_overlay / geo): turned squares 10⁵ 0.86 / 1.30 / 1.33, 10⁶ 9.4–10.4 / 13.1 / 14.0
//! (the same build with the reorder switched off: 19.4–19.7 s, user 16.9 s against
//! 7.5 s); axis-parallel squares 10⁵ 0.56 / 0.49 / 0.49, 10⁶ 9.5 / 5.2 / 5.3 (peak
//! 3.42 GB against 2.32 GB; the tracing 31% of the samples, page faults 25%, the
//! axis-parallel build 17%).
//!
//! Session 52: inputs with many long edges (`BOOLEAN_INPUT=nested|strips|diagonal|holes`,
//! [`long_edge_family`]: `BOOLEAN_N` nested square rings, thin horizontal strips or thin
//! diagonal strips, or a square with about `BOOLEAN_N` holes in rows, each against a
//! triangle across them). Before the session they were quadratic in three places: the
//! rounding check's grid listed an item in every cell of its box and, past 16 entries
//! per item, made the largest items "wide", met by every query (long edges across
//! the grid: all of them); a long diagonal edge's box also made a pair of it with
//! every point in that box (the pairs list alone reached 6.7 GB); and the components'
//! nearest-edge search scanned whole strips where one long edge came last in each.
//! Measured with the CLI on the same shapes (files, one call, 10³ → 10⁴): nested xor
//! 0.06 → 8.53 s, strips xor 0.05 → 15.2 s, diagonal intersection 0.17 → 13.2 s (6.7
//! GB), diagonal xor > 60 s (18.7 GB); 10⁴ → 10⁵ holes intersection 0.14 → 5.49 s. Now
//! a long edge is listed along its length (the cells of pieces of it, each a cell or two
//! long), tested exactly (after a float test with a stated margin) against the points
//! in its cells before it makes a pair, and where the entries would pass 64 per item
//! (and 2²⁴) the grid is made coarser instead of any item being met by every query; the
//! nearest-edge search gives up past 8 entries per edge and the hole sweep answers.
//! Outputs are byte-identical where the old build finished. One call, s, compgeom /
//! i_overlay / geo (geo's boolean operations run i_overlay, hence the equal times), at
//! 10³ and 10⁴: nested intersection 0.029 / 0.024 / 0.024 and 0.303 / 8.21 / 8.31, xor
//! 0.028 / 0.025 / 0.025 and 0.425 / 8.31 / 8.41; strips intersection 0.005 / 0.022 /
//! 0.023 and 0.087 / 0.368 / 0.355, xor 0.010 / 0.023 / 0.023 and 0.257 / 0.378 / 0.394;
//! diagonal intersection 0.026 / 0.187 / 0.183 and 0.555 / > 100 / > 100, xor 0.172 /
//! 0.209 / 0.200 and 3.42 / > 100 / > 100; holes (10⁴ and 10⁵) intersection 0.119 /
//! 1.50 / 1.57 and 0.51 / 16.0 / –, xor at 10⁴ 0.097 / 1.53 / 1.56. Still superlinear:
//! the diagonal xor (20× for 10× n: the parallel long edges share every cell of the band
//! they cross, so each point there meets about a hundred of them) and the overlay of
//! the diagonal strips (13–15 s at 10⁴, 0.17 s at 10³). The table's rows pay for it:
//! instructions a round, before / after, JTS intersection 10.84 M / 10.92–10.95 M, xor
//! 16.91 M / 17.00–17.07 M, dissolve 4.81 M / 4.86 M, water xor 129.4 M / 133.0–133.4 M
//! (the grid's two passes now ask per item whether it is long, the queries whether they
//! are; about half of the JTS change is code generation in the untouched noding,
//! `Found::test_by_points` 6.7 instructions a call more with the same calls).
//!
//! Session 53: the rounding check's search for near pairs was still quadratic where the
//! points and the long moved edges of a result gather in a few cells of its uniform
//! grid (about two cells per moved item over their extent): the diagonal strips (about
//! 600 long edges and as many points in each cell along the triangle's sides) and a
//! star of `BOOLEAN_N` spikes of length 10 n meeting near its centre (`spikes`, all
//! inner vertices within the unit circle). Where the first grid would list more than
//! 16 entries per item (and 2¹⁶), or its points meet more than 32 items per point and
//! item in their cells, the search now runs on a quadtree over the result's points
//! (leaves of at most 8 points, so small where the points are dense), the moved items
//! listed in the leaves their footprints may meet. Outputs byte-identical (CLI, all
//! four operations and the overlay, 10³ and 10⁴). One call, s, before → after:
//! diagonal intersection 0.033 → 0.024 at 10³, 0.60–0.74 → 0.24–0.31 at 10⁴, xor
//! 0.086 → 0.028 and 3.0–4.6 → 0.35; the spikes at 10⁴ (CLI, files) intersection 0.18
//! → 0.08, xor 0.54 → 0.12 (131 → 25 MB); their overlays 20.3 → 0.86–1.5 s (diagonal)
//! and 2.59 → 0.31 s (spikes, 477 → 82 MB). At 10⁵ (one call, s): diagonal 3.07 / 4.19
//! (intersection / xor), spikes 0.78 / 1.26, nested 4.0 / 4.9, strips 0.95 / 2.29: about
//! 10–13× for 10× n. i_overlay on the spikes: 0.018 s at 10³ (ours 0.017 / 0.014),
//! more than 120 s at 10⁴ (ours 0.061 / 0.18). The table's rows (instructions a round,
//! before / after): water xor 133.4 M / 133.1 M, JTS xor 17.06 M / 17.01 M, dissolve
//! 4.83 M / 4.88 M (+0.9%: code generation of the search, now one copy per index; the
//! dissolve's search keeps the grid, and its time did not move: 400 calls, median 0.66 /
//! 0.57–0.66 ms).

use crate::real_maps;
use crate::util::{alternate, median, ms, Rng};
use compgeom::overlay::{boolean, union_all, validity_problems, BooleanOp};
use compgeom::{MultiPolygon, Point2, Polygon};
use geo::{Area, BooleanOps};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use std::hint::black_box;
use std::time::{Duration, Instant};

fn star(rng: &mut Rng, n: usize, cx: f64, cy: f64) -> Vec<Point2> {
    let mut angles: Vec<f64> = (0..n).map(|_| std::f64::consts::TAU * rng.unit()).collect();
    angles.sort_by(f64::total_cmp);
    angles
        .into_iter()
        .map(|a| {
            // A smooth wavy outline plus noise of the order of the spacing: the two
            // outlines cross O(n) times (fully random radii would give Θ(n²) crossings).
            let r = 0.8 + 0.15 * (5.0 * a).sin() + 2.0 / n as f64 * rng.unit();
            Point2::new(cx + r * a.cos(), cy + r * a.sin())
        })
        .collect()
}

fn io_paths(m: &MultiPolygon) -> Vec<Vec<[f64; 2]>> {
    m.0.iter()
        .flat_map(|p| p.rings())
        .map(|r| r.iter().map(|p| [p.x, p.y]).collect())
        .collect()
}

fn io_area(shapes: &[Vec<Vec<[f64; 2]>>]) -> f64 {
    shapes
        .iter()
        .flatten()
        .map(|r| {
            (0..r.len())
                .map(|i| {
                    let (a, b) = (r[i], r[(i + 1) % r.len()]);
                    a[0] * b[1] - b[0] * a[1]
                })
                .sum::<f64>()
                / 2.0
        })
        .sum::<f64>()
        .abs()
}

/// A polygon set as i_overlay takes it: closed paths of points.
type IoPaths = Vec<Vec<[f64; 2]>>;

/// i_overlay's result (shapes of contours, the first the outer one) as polygons.
fn from_io(shapes: &[Vec<Vec<[f64; 2]>>]) -> MultiPolygon {
    let ring = |c: &Vec<[f64; 2]>| c.iter().map(|q| Point2::new(q[0], q[1])).collect();
    MultiPolygon(
        shapes
            .iter()
            .filter(|s| !s.is_empty())
            .map(|s| Polygon::new(ring(&s[0]), s[1..].iter().map(ring).collect()))
            .collect(),
    )
}

/// geo's result as polygons (its rings closed: the repeat is ignored by the check).
fn from_geo(m: &geo::MultiPolygon<f64>) -> MultiPolygon {
    let ring = |r: &geo::LineString<f64>| r.coords().map(|c| Point2::new(c.x, c.y)).collect();
    MultiPolygon(
        m.0.iter()
            .map(|p| Polygon::new(ring(p.exterior()), p.interiors().iter().map(ring).collect()))
            .collect(),
    )
}

/// Whether `m` is valid by the OGC rules, ring orientation aside (RFC 7946 asks for
/// counter-clockwise shells, OGC does not: the peers orient otherwise).
fn valid_as_ogc(m: &MultiPolygon) -> Result<bool, String> {
    let problems = validity_problems(m).map_err(|e| e.to_string())?;
    Ok(problems.iter().all(|p| p.message.contains("(RFC 7946)")))
}

/// Each pair of maps as i_overlay's input.
fn io_pairs(pairs: &[real_maps::MapPair]) -> Vec<(IoPaths, IoPaths)> {
    pairs
        .iter()
        .map(|p| (io_paths(&p.a), io_paths(&p.b)))
        .collect()
}

/// Each pair of maps as geo's input.
fn geo_pairs(pairs: &[real_maps::MapPair]) -> Vec<(geo::MultiPolygon, geo::MultiPolygon)> {
    pairs
        .iter()
        .map(|p| (geo_poly(&p.a), geo_poly(&p.b)))
        .collect()
}

fn geo_poly(m: &MultiPolygon) -> geo::MultiPolygon<f64> {
    geo::MultiPolygon::new(
        m.0.iter()
            .map(|p| {
                let ring = |r: &Vec<Point2>| {
                    geo::LineString::from(r.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>())
                };
                geo::Polygon::new(ring(&p.exterior), p.holes.iter().map(ring).collect())
            })
            .collect(),
    )
}

/// Three contenders timed in alternating rounds (the machine may be shared: a load spike
/// then hits all three alike): the best time of each, and the medians over rounds of the
/// per-round ratios ours / i_overlay and ours / geo.
/// The times of a row: each contender's best single call of the alternating rounds, the
/// median of the per-round ratios compgeom / i_overlay and compgeom / geo, and the same
/// ratios of the median call in a run of consecutive calls of one contender.
struct Timing {
    best: [Duration; 3],
    median_ratio: [f64; 2],
    in_a_row: [f64; 2],
}

/// Calls in a row per contender for [`Timing::in_a_row`] (2 when quick).
const IN_A_ROW: usize = 8;

/// Times compgeom (`a`), i_overlay (`b`) and geo (`c`): `runs` alternating rounds of one
/// call each, then each `calls` times in a row. Alternating rounds give each contender
/// the same machine state; runs in a row are how an application calling one library
/// over and over sees it (its arrays reused, its memory not handed back and faulted in
/// again between calls).
fn alternating(
    runs: usize,
    mut a: impl FnMut(),
    mut b: impl FnMut(),
    mut c: impl FnMut(),
) -> Timing {
    let rounds = alternate(runs, &mut [&mut a, &mut b, &mut c]);
    let mut best = [Duration::MAX; 3];
    for r in &rounds {
        for k in 0..3 {
            best[k] = best[k].min(r[k]);
        }
    }
    let ratio = |k: usize| median(rounds.iter().map(|r| ms(r[0]) / ms(r[k])).collect());
    let calls = if runs <= 1 { 2 } else { IN_A_ROW };
    let in_a_row = |f: &mut dyn FnMut()| {
        let times = alternate(calls, &mut [f]);
        median(times.iter().map(|t| ms(t[0])).collect())
    };
    let row = [in_a_row(&mut a), in_a_row(&mut b), in_a_row(&mut c)];
    Timing {
        best,
        median_ratio: [ratio(1), ratio(2)],
        in_a_row: [row[0] / row[1], row[0] / row[2]],
    }
}

fn row(name: &str, n: usize, t: &Timing, dev_io: f64) {
    let [ours, io, geo] = t.best.map(ms);
    println!(
        "| {name:<18} | {n:>7} | {ours:>9.2} | {io:>9.2} | {geo:>9.2} | {:>5.2} ({:>4.2}) | {:>5.2} ({:>4.2}) | {:>4.2} / {:>4.2} | {dev_io:.1e} |",
        ours / io,
        t.median_ratio[0],
        ours / geo,
        t.median_ratio[1],
        t.in_a_row[0],
        t.in_a_row[1],
    );
}

/// The four operations: name, compgeom's, i_overlay's and geo's.
const OPS: [(&str, BooleanOp, OverlayRule, geo::OpType); 4] = [
    (
        "intersection",
        BooleanOp::Intersection,
        OverlayRule::Intersect,
        geo::OpType::Intersection,
    ),
    (
        "union",
        BooleanOp::Union,
        OverlayRule::Union,
        geo::OpType::Union,
    ),
    (
        "difference",
        BooleanOp::Difference,
        OverlayRule::Difference,
        geo::OpType::Difference,
    ),
    ("xor", BooleanOp::Xor, OverlayRule::Xor, geo::OpType::Xor),
];

/// Run the group.
pub fn run(quick: bool) -> Result<(), String> {
    let mut rng = Rng::new(4);
    if let Ok(who) = std::env::var("BOOLEAN_ONE") {
        return one(&mut rng, &who);
    }
    // `BOOLEAN_ROWS=stars,squares,maps` (any subset; default all) picks the inputs.
    let rows = std::env::var("BOOLEAN_ROWS").unwrap_or_else(|_| "stars,squares,maps".into());
    let wanted = |r: &str| rows.split(',').any(|x| x.trim() == r);
    let sizes: &[usize] = match (wanted("stars"), quick) {
        (false, _) => &[],
        (true, true) => &[1_000, 10_000],
        (true, false) => &[1_000, 10_000, 100_000],
    };
    let runs = if quick { 1 } else { 5 };
    println!("boolean: best of {runs} alternating rounds, times in ms; ratio = compgeom / peer of the best times (median of per-round ratios); in a row = compgeom / i_overlay and / geo of the median call of {IN_A_ROW} consecutive calls of each; dev = |area − i_overlay area| / area");
    println!("| input              |       n |  compgeom | i_overlay |       geo |     /i_ov    |     /geo     |  in a row   | dev     |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for &n in sizes {
        let a = MultiPolygon(vec![Polygon::new(star(&mut rng, n, 0.0, 0.0), vec![])]);
        let b = MultiPolygon(vec![Polygon::new(star(&mut rng, n, 0.3, 0.0), vec![])]);
        let (pa, pb) = (io_paths(&a), io_paths(&b));
        let (ga, gb) = (geo_poly(&a), geo_poly(&b));
        for (name, op, rule, gop) in OPS {
            let ours = boolean(&a, &b, op).map_err(|e| e.to_string())?;
            let theirs = pa.overlay(&pb, rule, FillRule::EvenOdd);
            let (x, y) = (ours.area(), io_area(&theirs));
            let dev = (x - y).abs() / x.abs().max(1e-300);
            let t = alternating(
                runs,
                || drop(black_box(boolean(&a, &b, op).unwrap())),
                || drop(black_box(pa.overlay(&pb, rule, FillRule::EvenOdd))),
                || drop(black_box(ga.boolean_op(&gb, gop))),
            );
            let g = ga.boolean_op(&gb, gop).unsigned_area();
            if (g - x).abs() > 1e-6 * x.abs().max(1e-9) {
                println!("  note: geo area {g} vs compgeom {x}");
            }
            row(&format!("star {name}"), n, &t, dev);
        }
    }
    if wanted("squares") {
        squares_row(&mut rng, quick, runs, false)?;
        squares_row(&mut rng, quick, runs, true)?;
    }
    if wanted("maps") {
        real_map_rows(runs)?;
    }
    Ok(())
}

/// The union of many squares, axis-parallel or each `turned` by a random angle (then
/// their crossings are constructed points, and the result's rounding is checked on
/// a dense arrangement).
fn squares_row(rng: &mut Rng, quick: bool, runs: usize, turned: bool) -> Result<(), String> {
    let count = if quick { 1_000 } else { 10_000 };
    let squares = random_squares(rng, count, turned);
    let ps = io_paths(&squares);
    let empty: Vec<Vec<[f64; 2]>> = Vec::new();
    let gs: Vec<geo::Polygon<f64>> = geo_poly(&squares).0;
    let ours = union_all(&squares).map_err(|e| e.to_string())?;
    let theirs = ps.overlay(&empty, OverlayRule::Subject, FillRule::NonZero);
    let (x, y) = (ours.area(), io_area(&theirs));
    let t = alternating(
        runs,
        || drop(black_box(union_all(&squares).unwrap())),
        || {
            drop(black_box(ps.overlay(
                &empty,
                OverlayRule::Subject,
                FillRule::NonZero,
            )))
        },
        || drop(black_box(geo::unary_union(gs.iter()))),
    );
    let name = if turned {
        "turned square union"
    } else {
        "square union"
    };
    row(name, count, &t, (x - y).abs() / x);
    Ok(())
}

/// The real-map rows (see [`real_maps`]); a message instead when the cases folder is
/// absent. Fails when an answer's area differs from i_overlay's by more than 1e-6
/// relative (i_overlay snaps to a 32-bit grid; geo's area is only noted).
fn real_map_rows(runs: usize) -> Result<(), String> {
    let Some(dir) = real_maps::cases_dir() else {
        println!("real maps: skipped (no cases folder: set COMPGEOM_CASES)");
        return Ok(());
    };
    let water = real_maps::water_pair(&dir);
    let jts = real_maps::jts_robust_pairs(&dir);
    if water.is_none() {
        println!("real maps: earcut/fixtures/water-huge3.json missing, row skipped");
    }
    let check = |name: &str, x: f64, y: f64| {
        let dev = (x - y).abs() / x.abs().max(1e-300);
        if dev > 1e-6 {
            return Err(format!("{name}: area {x} vs i_overlay {y}"));
        }
        Ok(dev)
    };
    for (name, op, rule, gop) in OPS {
        if let Some(w) = &water {
            let (pa, pb) = (io_paths(&w.a), io_paths(&w.b));
            let (ga, gb) = (geo_poly(&w.a), geo_poly(&w.b));
            let x = boolean(&w.a, &w.b, op).map_err(|e| e.to_string())?.area();
            let dev = check(
                &w.name,
                x,
                io_area(&pa.overlay(&pb, rule, FillRule::EvenOdd)),
            )?;
            let t = alternating(
                runs,
                || drop(black_box(boolean(&w.a, &w.b, op).unwrap())),
                || drop(black_box(pa.overlay(&pb, rule, FillRule::EvenOdd))),
                || drop(black_box(ga.boolean_op(&gb, gop))),
            );
            let n = w.a.0.iter().flat_map(|p| p.rings()).map(Vec::len).sum();
            row(&format!("water {name}"), n, &t, dev);
        }
        if !jts.is_empty() {
            let (io, geo) = (io_pairs(&jts), geo_pairs(&jts));
            let mut dev: f64 = 0.0;
            for (p, (pa, pb)) in jts.iter().zip(&io) {
                let x = boolean(&p.a, &p.b, op).map_err(|e| e.to_string())?.area();
                let y = io_area(&pa.overlay(pb, rule, FillRule::EvenOdd));
                // i_overlay rounds to a 32-bit grid scaled to the largest coordinate
                // (these maps sit far from the origin: cells up to ~1e-3 at 5e6): allow
                // every boundary point to move by a few cells.
                let max = p.a.0.iter().chain(&p.b.0).flat_map(|q| q.rings()).flatten();
                let max = max.fold(0.0f64, |m, q| m.max(q.x.abs()).max(q.y.abs()));
                let allowed = (perimeter(&p.a) + perimeter(&p.b)) * max * 2f64.powi(-28);
                if (x - y).abs() > allowed {
                    return Err(format!("{}: {name} area {x} vs i_overlay {y}", p.name));
                }
                let scale = p.a.area().abs() + p.b.area().abs();
                dev = dev.max((x - y).abs() / scale);
            }
            let t = alternating(
                runs,
                || {
                    for p in &jts {
                        drop(black_box(boolean(&p.a, &p.b, op).unwrap()));
                    }
                },
                || {
                    for (pa, pb) in &io {
                        drop(black_box(pa.overlay(pb, rule, FillRule::EvenOdd)));
                    }
                },
                || {
                    for (ga, gb) in &geo {
                        drop(black_box(ga.boolean_op(gb, gop)));
                    }
                },
            );
            let n = jts
                .iter()
                .flat_map(|p| p.a.0.iter().chain(&p.b.0))
                .flat_map(|p| p.rings())
                .map(Vec::len)
                .sum();
            row(&format!("jts×{} {name}", jts.len()), n, &t, dev);
            // What the answers are worth (outside the clock): results that are not valid.
            let mut invalid = [0usize; 3];
            for (k, p) in jts.iter().enumerate() {
                let results = [
                    boolean(&p.a, &p.b, op).map_err(|e| e.to_string())?,
                    from_io(&io[k].0.overlay(&io[k].1, rule, FillRule::EvenOdd)),
                    from_geo(&geo[k].0.boolean_op(&geo[k].1, gop)),
                ];
                for (count, result) in invalid.iter_mut().zip(&results) {
                    *count += usize::from(!valid_as_ogc(result)?);
                }
            }
            println!(
                "  {name}: results not valid (OGC rules, ring orientation aside): compgeom {}, i_overlay {}, geo {} of {}",
                invalid[0],
                invalid[1],
                invalid[2],
                jts.len()
            );
        }
    }
    if let Some(d) = real_maps::geos_837(&dir) {
        let pa = io_paths_oriented(&d.a);
        let empty: Vec<Vec<[f64; 2]>> = Vec::new();
        let gs = geo_poly(&d.a).0;
        let x = union_all(&d.a).map_err(|e| e.to_string())?.area();
        let dev = check(
            &d.name,
            x,
            io_area(&pa.overlay(&empty, OverlayRule::Subject, FillRule::NonZero)),
        )?;
        let t = alternating(
            runs,
            || drop(black_box(union_all(&d.a).unwrap())),
            || {
                drop(black_box(pa.overlay(
                    &empty,
                    OverlayRule::Subject,
                    FillRule::NonZero,
                )))
            },
            || drop(black_box(geo::unary_union(gs.iter()))),
        );
        let n = d.a.0.iter().flat_map(|p| p.rings()).map(Vec::len).sum();
        row("geos-837 dissolve", n, &t, dev);
        let results = [
            union_all(&d.a).map_err(|e| e.to_string())?,
            from_io(&pa.overlay(&empty, OverlayRule::Subject, FillRule::NonZero)),
            from_geo(&geo::unary_union(gs.iter())),
        ];
        let valid: Vec<bool> = results.iter().map(valid_as_ogc).collect::<Result<_, _>>()?;
        println!(
            "  dissolve: result valid (OGC rules, ring orientation aside): compgeom {}, i_overlay {}, geo {}",
            valid[0], valid[1], valid[2]
        );
    }
    Ok(())
}

/// `rounds` rounds of the `calls` (one each, in turn), each call timed on its own after
/// what `BOOLEAN_BRANCHY` and `BOOLEAN_THRASH_KB` ask for (unpredictable branches on a
/// few registers, which only disturb the branch predictor; a write to every cache line
/// of a buffer that size, which evicts data from the caches); prints each call's
/// median and best time. A call repeated alone on the same input runs with a branch
/// predictor trained on that very input: these show how far that flatters it.
fn disturbed_rounds(rounds: usize, calls: &[(&str, &dyn Fn())]) {
    let var = |name: &str| -> usize {
        std::env::var(name)
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(0)
    };
    let branches = var("BOOLEAN_BRANCHY");
    let mut buffer = vec![0u8; var("BOOLEAN_THRASH_KB") << 10];
    let mut times = vec![Vec::with_capacity(rounds); calls.len()];
    let mut x = 0x9E37_79B9_7F4A_7C15u64;
    for round in 0..rounds {
        for (k, (_, call)) in calls.iter().enumerate() {
            for b in buffer.iter_mut().step_by(64) {
                *b = b.wrapping_add(round as u8);
            }
            let mut acc = 0u64;
            for _ in 0..branches {
                // xorshift64: a branch on its low bits is a coin toss.
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                if x & 1 == 0 {
                    acc += x & 0xff;
                } else if x & 2 == 0 {
                    acc ^= x;
                } else {
                    acc = acc.rotate_left(3);
                }
            }
            black_box(acc);
            let start = Instant::now();
            call();
            times[k].push(ms(start.elapsed()));
        }
    }
    black_box(&buffer);
    for ((name, _), t) in calls.iter().zip(times) {
        let best = t.iter().copied().fold(f64::INFINITY, f64::min);
        println!("{name}: median {:.4} ms, best {best:.4} ms", median(t));
    }
}

fn perimeter(m: &MultiPolygon) -> f64 {
    m.0.iter()
        .flat_map(|p| p.rings())
        .flat_map(|r| {
            (0..r.len())
                .map(|i| (r[(i + 1) % r.len()].x - r[i].x).hypot(r[(i + 1) % r.len()].y - r[i].y))
        })
        .sum()
}

/// The paths of a polygon set with shells counter-clockwise and holes clockwise, so
/// i_overlay's non-zero rule reads each polygon as its shell minus its holes (what
/// `union_all` does whatever the input orientation).
fn io_paths_oriented(m: &MultiPolygon) -> Vec<Vec<[f64; 2]>> {
    let signed = |r: &Vec<[f64; 2]>| {
        (0..r.len())
            .map(|i| {
                let (a, b) = (r[i], r[(i + 1) % r.len()]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>()
    };
    m.0.iter()
        .flat_map(|p| {
            p.rings().enumerate().map(|(k, r)| {
                let mut path: Vec<[f64; 2]> = r.iter().map(|p| [p.x, p.y]).collect();
                if (signed(&path) > 0.0) != (k == 0) {
                    path.reverse();
                }
                path
            })
        })
        .collect()
}

/// `BOOLEAN_ONE=ours|io|geo` (and `BOOLEAN_N`, default 1e5;
/// `BOOLEAN_INPUT=star|squares|turned|water|jts|ngons|dissolve`, or one of the long-edge
/// families `nested|strips|diagonal|spikes|holes` ([`long_edge_family`], `BOOLEAN_N` of them,
/// intersected with a triangle, or `BOOLEAN_OP`; one call, timed), `BOOLEAN_REPS` calls except
/// for the squares): run one contender on the star union, the squares input (`turned`:
/// turned by random angles; `BOOLEAN_SPREAD=1`: over a larger square, at the density of
/// 10⁴ in the unit square; either way the call's own time on stderr), the water
/// map union, the unions of the 52 JTS pairs (the stars, the water and the pairs also
/// another `BOOLEAN_OP`), the same
/// operation on 52 pairs of regular `BOOLEAN_K`-gons (default 4) or the GEOS-837
/// dissolve (`union_all`), for instruction counts (`valgrind --tool=callgrind`). The dissolve also takes
/// `BOOLEAN_ONE=all` (the three alternated, one call each per round, as the table
/// does) and prints each contender's median and best call ([`disturbed_rounds`]).
/// `BOOLEAN_ONE=pairs` with the JTS or n-gon pairs prints every pair's best of
/// `BOOLEAN_REPS` (default 50) calls of the three instead ([`per_pair`]); `BOOLEAN_PAIR=text` keeps the JTS pairs whose names
/// contain it.
fn one(rng: &mut Rng, who: &str) -> Result<(), String> {
    let n: usize = std::env::var("BOOLEAN_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(100_000);
    // (One call by default; `pairs` times the best of 50 per pair, warm.)
    let reps: usize = std::env::var("BOOLEAN_REPS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if who == "pairs" { 50 } else { 1 });
    let input = std::env::var("BOOLEAN_INPUT").unwrap_or_default();
    if input == "squares" || input == "turned" {
        let sq = random_squares(rng, n, input == "turned");
        let ps = io_paths(&sq);
        let empty: Vec<Vec<[f64; 2]>> = Vec::new();
        let gs: Vec<geo::Polygon<f64>> = geo_poly(&sq).0;
        // (The call's own time on stderr: the process's includes making the input.)
        let _timer = CallTimer(std::time::Instant::now());
        match who {
            "ours" => drop(black_box(union_all(&sq).map_err(|e| e.to_string())?)),
            "io" => drop(black_box(ps.overlay(
                &empty,
                OverlayRule::Subject,
                FillRule::NonZero,
            ))),
            _ => drop(black_box(geo::unary_union(gs.iter()))),
        }
        return Ok(());
    }
    let dissolve = std::env::var("BOOLEAN_INPUT").is_ok_and(|s| s == "dissolve");
    if dissolve {
        let dir = real_maps::cases_dir().ok_or("no cases folder (COMPGEOM_CASES)")?;
        let d = real_maps::geos_837(&dir).ok_or("no GEOS-837 case")?;
        let pa = io_paths_oriented(&d.a);
        let empty: Vec<Vec<[f64; 2]>> = Vec::new();
        let gs = geo_poly(&d.a).0;
        let ours = || drop(black_box(union_all(&d.a).unwrap()));
        let io = || {
            drop(black_box(pa.overlay(
                &empty,
                OverlayRule::Subject,
                FillRule::NonZero,
            )))
        };
        let geo = || drop(black_box(geo::unary_union(gs.iter())));
        let who = if who == "all" { "ours,io,geo" } else { who };
        let calls: Vec<(&str, &dyn Fn())> = who
            .split(',')
            .map(|name| -> (&str, &dyn Fn()) {
                match name {
                    "ours" => ("ours", &ours),
                    "io" => ("io", &io),
                    _ => ("geo", &geo),
                }
            })
            .collect();
        disturbed_rounds(reps, &calls);
        return Ok(());
    }
    if input == "jts" || input == "ngons" {
        let jts = if input == "jts" {
            let dir = real_maps::cases_dir().ok_or("no cases folder (COMPGEOM_CASES)")?;
            // `BOOLEAN_PAIR=text`: only the pairs whose names contain it.
            let only = std::env::var("BOOLEAN_PAIR").unwrap_or_default();
            let mut pairs = real_maps::jts_robust_pairs(&dir);
            pairs.retain(|p| p.name.contains(&only));
            pairs
        } else {
            // 52 copies of two regular k-gons of radius 1, centres 0.5 apart (two
            // crossings): the cost of a call on a small input.
            let k: usize = std::env::var("BOOLEAN_K")
                .ok()
                .and_then(|s| s.parse().ok())
                .unwrap_or(4)
                .max(3);
            let ngon = |cx: f64| {
                let pts = (0..k)
                    .map(|i| {
                        let a = std::f64::consts::TAU * i as f64 / k as f64;
                        Point2::new(cx + a.cos(), a.sin())
                    })
                    .collect();
                MultiPolygon(vec![Polygon::new(pts, vec![])])
            };
            (0..52)
                .map(|_| real_maps::MapPair {
                    name: format!("{k}-gons"),
                    a: ngon(0.0),
                    b: ngon(0.5),
                })
                .collect()
        };
        let (io, geo) = (io_pairs(&jts), geo_pairs(&jts));
        // `BOOLEAN_OP=intersection|difference|xor` for another operation than the union.
        let name = std::env::var("BOOLEAN_OP").unwrap_or_else(|_| "union".into());
        let (_, op, io_op, geo_op) = *OPS
            .iter()
            .find(|o| o.0 == name)
            .ok_or("BOOLEAN_OP: intersection, union, difference or xor")?;
        if who == "pairs" {
            per_pair(&jts, &io, &geo, op, io_op, geo_op, reps.max(1));
            return Ok(());
        }
        for _ in 0..reps {
            for (k, p) in jts.iter().enumerate() {
                match who {
                    "ours" => drop(black_box(
                        boolean(&p.a, &p.b, op).map_err(|e| e.to_string())?,
                    )),
                    "io" => drop(black_box(io[k].0.overlay(
                        &io[k].1,
                        io_op,
                        FillRule::EvenOdd,
                    ))),
                    _ => drop(black_box(geo[k].0.boolean_op(&geo[k].1, geo_op))),
                }
            }
        }
        return Ok(());
    }
    if let Some((a, b)) = long_edge_family(&input, n) {
        // One call, its own time on stderr (the input's set-up is not timed).
        let name = std::env::var("BOOLEAN_OP").unwrap_or_else(|_| "intersection".into());
        let (_, op, io_op, geo_op) = *OPS
            .iter()
            .find(|o| o.0 == name)
            .ok_or("BOOLEAN_OP: intersection, union, difference or xor")?;
        let (pa, pb) = (io_paths(&a), io_paths(&b));
        let (ga, gb) = (geo_poly(&a), geo_poly(&b));
        let _timer = CallTimer(std::time::Instant::now());
        match who {
            "ours" => drop(black_box(boolean(&a, &b, op).map_err(|e| e.to_string())?)),
            "io" => drop(black_box(pa.overlay(&pb, io_op, FillRule::EvenOdd))),
            _ => drop(black_box(ga.boolean_op(&gb, geo_op))),
        }
        return Ok(());
    }
    let water = std::env::var("BOOLEAN_INPUT").is_ok_and(|s| s == "water");
    let (a, b) = if water {
        let dir = real_maps::cases_dir().ok_or("no cases folder (COMPGEOM_CASES)")?;
        let w = real_maps::water_pair(&dir).ok_or("no earcut/fixtures/water-huge3.json")?;
        (w.a, w.b)
    } else {
        (
            MultiPolygon(vec![Polygon::new(star(rng, n, 0.0, 0.0), vec![])]),
            MultiPolygon(vec![Polygon::new(star(rng, n, 0.3, 0.0), vec![])]),
        )
    };
    let (pa, pb) = (io_paths(&a), io_paths(&b));
    let (ga, gb) = (geo_poly(&a), geo_poly(&b));
    // `BOOLEAN_OP` as for the JTS pairs (default the union).
    let name = std::env::var("BOOLEAN_OP").unwrap_or_else(|_| "union".into());
    let (_, op, io_op, geo_op) = *OPS
        .iter()
        .find(|o| o.0 == name)
        .ok_or("BOOLEAN_OP: intersection, union, difference or xor")?;
    for _ in 0..reps {
        match who {
            "ours" => drop(black_box(boolean(&a, &b, op).map_err(|e| e.to_string())?)),
            "io" => drop(black_box(pa.overlay(&pb, io_op, FillRule::EvenOdd))),
            _ => drop(black_box(ga.boolean_op(&gb, geo_op))),
        }
    }
    Ok(())
}

/// `BOOLEAN_ONE=pairs`: each pair's best time of `reps` calls for the three contenders
/// (µs), worst excess over geo first: where a row's cost comes from.
#[allow(clippy::too_many_arguments)]
fn per_pair(
    pairs: &[real_maps::MapPair],
    io: &[(IoPaths, IoPaths)],
    geo: &[(geo::MultiPolygon, geo::MultiPolygon)],
    op: BooleanOp,
    io_op: OverlayRule,
    geo_op: geo::OpType,
    reps: usize,
) {
    let best = |f: &dyn Fn()| {
        (0..reps)
            .map(|_| {
                let t = Instant::now();
                f();
                t.elapsed().as_secs_f64() * 1e6
            })
            .fold(f64::INFINITY, f64::min)
    };
    let mut rows: Vec<(String, usize, f64, f64, f64)> = pairs
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let ours = best(&|| drop(black_box(boolean(&p.a, &p.b, op).unwrap())));
            let i = best(&|| {
                drop(black_box(io[k].0.overlay(
                    &io[k].1,
                    io_op,
                    FillRule::EvenOdd,
                )))
            });
            let g = best(&|| drop(black_box(geo[k].0.boolean_op(&geo[k].1, geo_op))));
            let n =
                p.a.0
                    .iter()
                    .chain(&p.b.0)
                    .flat_map(|q| q.rings())
                    .map(Vec::len)
                    .sum();
            (p.name.clone(), n, ours, i, g)
        })
        .collect();
    rows.sort_by(|x, y| (y.2 - y.4).total_cmp(&(x.2 - x.4)));
    let sum = |f: fn(&(String, usize, f64, f64, f64)) -> f64| rows.iter().map(f).sum::<f64>();
    println!(
        "sum µs: compgeom {:.1}, i_overlay {:.1}, geo {:.1}",
        sum(|r| r.2),
        sum(|r| r.3),
        sum(|r| r.4)
    );
    for (name, n, ours, i, g) in &rows {
        println!(
            "{ours:8.2} {i:8.2} {g:8.2}  {:5.2} {:5.2}  n={n:5}  {name}",
            ours / i,
            ours / g
        );
    }
}

/// Inputs with many long edges, against a triangle across them (how cost grows with
/// `n` where long edges share the cells of every grid):
/// - `nested`: `n` nested square rings (each a polygon with its hole), the triangle
///   cutting through all of them;
/// - `strips`: `n` long thin horizontal quadrilaterals one above the other;
/// - `diagonal`: `n` long thin parallel diagonal quadrilaterals side by side;
/// - `spikes`: one star of `n` spikes of length 10 `n` meeting near its centre;
/// - `holes`: one square with about `n` square holes in rows (a field of holes) and
///   the triangle's long side across the rows.
fn long_edge_family(name: &str, n: usize) -> Option<(MultiPolygon, MultiPolygon)> {
    let p = Point2::new;
    let k = n as f64;
    let square = |x0: f64, x1: f64| vec![p(x0, x0), p(x1, x0), p(x1, x1), p(x0, x1)];
    let triangle = |s: f64| {
        MultiPolygon(vec![Polygon::new(
            vec![p(0.5, 0.3), p(s + 0.7, 0.9), p(0.8, s + 0.2)],
            vec![],
        )])
    };
    let a = match name {
        "nested" => (0..n)
            .map(|i| {
                let (e, w) = (2.0 * i as f64, 4.0 * k);
                Polygon::new(square(e, w - e), vec![square(e + 1.0, w - e - 1.0)])
            })
            .collect(),
        "strips" => (0..n)
            .map(|i| {
                let y = 2.0 * i as f64;
                let w = 10.0 * k;
                Polygon::new(
                    vec![p(0.0, y), p(w, y + 0.3), p(w, y + 1.0), p(0.0, y + 1.1)],
                    vec![],
                )
            })
            .collect(),
        "diagonal" => (0..n)
            .map(|i| {
                let (x, w) = (i as f64, 10.0 * k);
                Polygon::new(
                    vec![p(x, 0.0), p(x + 0.5, 0.0), p(x + 0.5 + w, w), p(x + w, w)],
                    vec![],
                )
            })
            .collect(),
        "spikes" => {
            // A star of n spikes from radius 10 n to 1, all meeting near its centre.
            let outline = (0..2 * n)
                .map(|i| {
                    let a = std::f64::consts::PI * i as f64 / k;
                    let r = if i % 2 == 0 { 10.0 * k } else { 1.0 };
                    p(r * a.cos(), r * a.sin())
                })
                .collect();
            let a = MultiPolygon(vec![Polygon::new(outline, vec![])]);
            return Some((a, triangle(9.0 * k)));
        }
        "holes" => {
            let rows = (k.sqrt().ceil() as usize).max(1);
            let side = 2.0 * rows as f64 + 1.0;
            let holes = (0..rows * rows)
                .map(|h| {
                    let (x, y) = ((2 * (h % rows) + 1) as f64, (2 * (h / rows) + 1) as f64);
                    vec![p(x, y), p(x, y + 1.0), p(x + 1.0, y + 1.0), p(x + 1.0, y)]
                })
                .collect();
            let a = MultiPolygon(vec![Polygon::new(square(0.0, side), holes)]);
            return Some((a, triangle(side - 1.0)));
        }
        _ => return None,
    };
    Some((MultiPolygon(a), triangle(4.0 * k)))
}

/// Prints the time since it was made when dropped.
struct CallTimer(std::time::Instant);

impl Drop for CallTimer {
    fn drop(&mut self) {
        eprintln!("call {:.3} s", self.0.elapsed().as_secs_f64());
    }
}

/// `count` squares with random corners in the unit square (see `BOOLEAN_SPREAD` below)
/// and sides 0.005..0.025 (so they overlap in chains), axis-parallel or each `turned`
/// by a random angle below 90°
/// about that corner.
fn random_squares(rng: &mut Rng, count: usize, turned: bool) -> MultiPolygon {
    // `BOOLEAN_SPREAD=1`: over a square of side sqrt(count / 10⁴), at the density of
    // 10⁴ squares in the unit square (how cost grows with n, not with the density).
    let side = if std::env::var("BOOLEAN_SPREAD").is_ok_and(|s| s == "1") {
        (count as f64 / 1e4).sqrt()
    } else {
        1.0
    };
    MultiPolygon(
        (0..count)
            .map(|_| {
                let (x, y, w) = (
                    side * rng.unit(),
                    side * rng.unit(),
                    0.005 + 0.02 * rng.unit(),
                );
                // The sides' direction: (w, 0), or turned by a random angle.
                let (dx, dy) = if turned {
                    let a = std::f64::consts::FRAC_PI_2 * rng.unit();
                    (w * a.cos(), w * a.sin())
                } else {
                    (w, 0.0)
                };
                Polygon::new(
                    vec![
                        Point2::new(x, y),
                        Point2::new(x + dx, y + dy),
                        Point2::new(x + dx - dy, y + dy + dx),
                        Point2::new(x - dy, y + dx),
                    ],
                    vec![],
                )
            })
            .collect(),
    )
}
