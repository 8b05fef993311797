//! `compgeom-bench intersect`: segment intersection (book §2.1) against geo.
//!
//! Peers, on the same segments in the same run:
//! * geo 0.33's `sweep::Intersections` iterator (sorts by x, then tests every pair whose
//!   x-ranges overlap with `line_intersection`; yields one item per meeting pair);
//! * a plain O(n²) loop over all pairs with geo's `line_intersection` (a bounding-box
//!   test first, which only skips the call), run two ways: counting the meeting pairs
//!   (compared with compgeom's count) and collecting one `(i, j, LineIntersection)` per
//!   meeting pair into a `Vec` (compared with compgeom's find).
//!
//! compgeom is timed three times: `find_intersections` (the default: exact tests of the
//! pairs whose boxes overlap, found with a uniform grid, or the sweep when many pairs
//! share grid cells without meeting), `sweep_intersections` (the book's Bentley–Ottmann
//! sweep), and `count_intersections` (the exact numbers of points, overlaps and meeting
//! pairs, nothing materialised).
//!
//! What each side produces (the comparisons the table makes):
//! * geo's iterator yields one `(line, line, LineIntersection)` per meeting pair, the
//!   point computed in plain `f64` (not correctly rounded), coincident points not merged.
//!   `count()` consumes it without storing; `collect()` stores it (a `Vec` of 104-byte
//!   items).
//! * `count_intersections` against geo's `count()`: both test every candidate pair and
//!   keep nothing; compgeom's test is exact and it merges coincident points exactly
//!   (the count of distinct points), but computes no coordinates, while geo computes an
//!   `f64` point per pair and throws it away.
//! * `find_intersections` against geo's `collect()`: both materialise the answer;
//!   compgeom's holds more (one 40-byte record per distinct point with correctly
//!   rounded coordinates, sorted U/L/C lists and, for a crossing, the pair of segments
//!   that defines its exact point; maximal overlaps; sweep order).
//! * The O(n²) loops likewise: the counting loop against `count_intersections`, the
//!   collecting loop (a `Vec` of 64-byte items) against `find_intersections`. Until
//!   session 24 the table set the counting loop against `find_intersections`.
//!
//! Answers are compared once, outside the clock, by the number of meeting pairs
//! (compgeom's `pair_count` for both methods and `pairs` of the count, against the
//! number of pairs geo yields).
//!
//! `COMPGEOM_BENCH_ONLY=short|long|grid` runs one of the three inputs.
//! `COMPGEOM_BENCH_LONG_N=n` runs only the counts on n long random segments (compgeom
//! against geo's `count()`, alternating), for the growth of the dense case.
//!
//! ## Measured
//!
//! Session 5 (branch s5-isect), 2-core machine shared with four other builds; seconds,
//! best of 5 interleaved; ratio = geo / compgeom (> 1: compgeom faster). Two runs a
//! minute apart, to show the spread under load.
//!
//! | input | n | points | count vs geo count() | find vs geo collect() | load |
//! |---|---:|---:|---|---|---:|
//! | short random | 1e5 | 51 003 | 0.0170 vs 0.1758 (10.3×) | 0.0194 vs 0.1776 (9.2×) | 2.8 |
//! | long random | 1e3 | 251 108 | 0.0105 vs 0.0094 (0.90×) | 0.0384 vs 0.0101 (0.26×) | 2.8 |
//! | 100×100 grid | 1e4 | 27 344 + 916 overlaps | 0.0157 vs 0.0220 (1.40×) | 0.0141 vs 0.0225 (1.59×) | 2.8 |
//! | short random | 1e5 | 51 003 | 0.0499 vs 0.2992 (6.0×) | 0.0568 vs 0.2591 (4.6×) | 1.9 |
//! | long random | 1e3 | 251 108 | 0.0081 vs 0.0095 (1.17×) | 0.0263 vs 0.0101 (0.38×) | 1.9 |
//! | 100×100 grid | 1e4 | 27 344 + 916 overlaps | 0.0128 vs 0.0223 (1.75×) | 0.0146 vs 0.0228 (1.56×) | 1.9 |
//!
//! Counts alone (`COMPGEOM_BENCH_LONG_N`, best of 3, load 2–3): n = 1e3 0.0255 vs 0.0135
//! (0.53×, a fresh process: page faults on the record buffers), 3e3 (2.3M points) 0.153
//! vs 0.090 (0.59×), 1e4 (25.1M points) 1.60 vs 0.99 (0.62×). compgeom's count grows
//! 1e3→1e4 by 150–200× for 100× the points (records outgrow the caches), geo's by about
//! 100×. Instruction counts (callgrind, one thread, long 1e3): find 574M → 305M
//! (allocation-free points, bucket sort, shared double-double parameter in the rounding,
//! static filter), count 160M → 115M. Without FMA the certified rounding of a crossing
//! still costs about 550 instructions (Dekker products): the find gap on the dense case.
//!
//! Session 6 (branch s6-isect), 2-core machine shared with three other helpers' builds
//! (load 6.7–9: wall figures swing ×2–3 between runs, geo's included). Full run, same
//! binary pair run back to back, ratio = geo / compgeom:
//!
//! | input | n | count vs geo count() | find vs geo collect() | load |
//! |---|---:|---|---|---:|
//! | short random, before | 1e5 | 0.0615 vs 0.3926 (6.38×) | 0.0805 vs 0.3873 (4.81×) | 7.3 |
//! | short random, after | 1e5 | 0.0636 vs 0.3139 (4.93×) | 0.0647 vs 0.3069 (4.74×) | 6.8 |
//! | long random, before | 1e3 | 0.0170 vs 0.0160 (0.94×) | 0.0701 vs 0.0191 (0.27×) | 7.3 |
//! | long random, after | 1e3 | 0.0224 vs 0.0160 (0.71×) | 0.0413 vs 0.0178 (0.43×) | 6.8 |
//! | 100×100 grid, before | 1e4 | 0.0373 vs 0.0621 (1.67×) | 0.0242 vs 0.0527 (2.18×) | 7.3 |
//! | 100×100 grid, after | 1e4 | 0.0338 vs 0.0319 (0.94×) | 0.0285 vs 0.0335 (1.18×) | 6.8 |
//!
//! (The grid row's geo time halved between the two runs: load, not code.) Figures that
//! hold under this load, long random 1e3 (`examples/intersect_profile`, one thread):
//! instructions (callgrind) find 333M → 283M, count 140M → 128M; CPU time per call
//! (`perf stat` task-clock, 20 calls) find 60 → 32 ms, count 31 → 24 ms. The find gain
//! is mostly memory: `IntersectionPoint` went from 184 to 56 bytes (no exact point copy,
//! lists inline as ranges into the sorted pair), which took the page faults of a call
//! from ~11k to ~1k (sys time 25 ms → 2 ms per call). Also: the rounding runs in two
//! lanes (SSE2; 590 → 480 instructions per crossing), and the bucket sort and the
//! grouping of the sorted records run on the rayon pool. Count at 1e4 (25.1M points):
//! CPU 2.7–4.1 s before, 3.1–3.9 s after (no change measurable under this load).
//! Still missing: find on long random is below geo (geo's whole `count()` is ~109M
//! instructions by callgrind, compgeom's rounding alone ~120M: about 480 instructions per
//! crossing for correct rounding without FMA).
//!
//! End of session 7, all branches merged, machine quiet (load 1–2.5), ratio geo /
//! compgeom (2 threads): full run short 1e5 7.44× / 6.89×, grid 1e4 1.62× / 1.64×
//! (count / find; grid alone 1.35–1.62× / 1.52–2.04×, the session-6 binary the same
//! within noise); long 1e3 alone, three runs after the last merge: count 2.04–2.20×
//! (4.8–5.1 ms against 10.4–10.5), find 0.65–0.78× (14.0–16.8 ms against 10.8–11.0),
//! so long find is still short of geo.
//!
//! Session 8 (all four branches merged; quiet machine, load 0.5–2): the rounding's exact
//! products are fused multiply-adds chosen at run time on x86-64 (one generic fast path,
//! Dekker or FMA; callgrind ~380 → ~175 instructions per crossing, whole find 256.6M →
//! 210.4M single-threaded), crossings rounded eight lanes at a time in the scan, groups
//! marked inside the bucket sort and points built from the marks (−9% instructions on
//! long find). Long 1e3, six runs, ratio geo collect / compgeom find: 1.02×, 0.76×,
//! 0.90×, 0.68×, 0.78×, 0.68× (find 10.8–17.0 ms, wide spread; geo 11.0–12.3 ms);
//! alternated with the session-7 binary at load ~2: new 11.0–12.6 ms, old 13.4–15.5 ms.
//! Count 1.84–2.29×. Short 1e5 6.61–6.85× / 5.62–5.63×, grid 1e4 1.45× / 2.02×
//! (count / find). Long find reaches geo only in its best runs: still open.
//!
//! Session 7 (branch s7-round, the rounding only), load 7–8, full run:
//!
//! | input | n | count vs geo count() | find vs geo collect() | load |
//! |---|---:|---|---|---:|
//! | short random | 1e5 | 0.0738 vs 0.4384 (5.94×) | 0.0700 vs 0.4158 (5.94×) | 7.8 |
//! | long random | 1e3 | 0.0355 vs 0.0257 (0.72×) | 0.0637 vs 0.0267 (0.42×) | 7.8 |
//! | long random (`ONLY=long`) | 1e3 | 0.0275 vs 0.0185 (0.67×) | 0.0475 vs 0.0191 (0.40×) | 7.2 |
//! | 100×100 grid | 1e4 | 0.0350 vs 0.0484 (1.38×) | 0.0402 vs 0.0502 (1.25×) | 7.8 |
//!
//! No rounding change beat the session-6 path in the scan (`examples/intersect_profile
//! find 1000`, one thread, session-6 binary against each candidate alternately, 10–20
//! rounds of best-of-5, median of per-round ratios, load 4–7): one branch-free lane per
//! crossing 1.00 (kept: ~430 instead of ~470 instructions per crossing, same time);
//! eight crossings in eight lanes 0.95–0.97; exact fixed point (i128 determinants and
//! residual) ~0.65; FMA through libm calls equal to Dekker (isolated: 54.8 vs 53.8 ns
//! per crossing). `-C target-cpu=native` (FMA, AVX): find 1.19× faster (median), which
//! the default target does not get. Details in `intersect/round.rs`.
//!
//! Session 7 (branch s7-pairs): candidate pairs of long segments by a sort and sweep
//! along one axis (each pair with overlapping boxes looked at once: 333k looks instead
//! of the grid's 591k at 1e3), the scan in equal-work chunks with reserved buffers, the
//! bucket sort straight from the scan's parts on the rayon pool (no concatenation), and
//! the count grouped per segment in cache when no pair overlaps (no global sort, O(n)
//! memory). Machine loaded by three other helpers (load 2.4–9), so CPU time and
//! instruction counts are the figures that hold; `examples/intersect_profile`, one
//! thread, 20 calls, before → after:
//!
//! | long random 1e3 | before | after |
//! |---|---:|---:|
//! | count CPU per call (perf task-clock, load ~9) | 25.7 ms | 9.3 ms |
//! | count page faults per call | 3 400 | 20 |
//! | count instructions (callgrind) | 128.6M | 104.7M |
//! | find CPU per call | 34 ms | 26 ms |
//! | find instructions | 284M | 280M (rounding 122M of it, unchanged) |
//! | count at 1e4 (25M points): CPU per call, peak RSS | 2.9 s, 1.38 GB | 1.0 s, 8 MB |
//!
//! Bench rows, same run, ratio = geo / compgeom (2 threads; wall figures swing ×2 under
//! this load, geo's included): at load 2.4 short 5.92× / 4.59×, long 0.75× / 0.59×,
//! grid 1.33× / 1.25× (count / find); the old binary right after (load 3.5): short
//! 5.38× / 5.10×, long 0.69× / 0.49×, grid 1.32× / 1.57×. Counts alone at 1e4 (load
//! 8.7): 4.23 s vs geo 1.51 s (0.36×) before, 2.72 s vs 1.86 s (0.68×) after.
//!
//! Session 7 (branch s7-round2): the per-segment part of the rounding (direction as an
//! exact double-double, Veltkamp splits of its leading parts, range check) computed once
//! per segment (`round::Prepared`) instead of per crossing. `examples/intersect_profile
//! find 1000`, one thread, callgrind (241 717 crossings): whole run 270.0M → 252.8M
//! instructions, rounding 115.5M → 98.6M inclusive (478 → 408 per crossing). Wall, same
//! load (5–7, three other helpers): example binaries alternating, 8 rounds of best-of-5,
//! best 20.2 → 19.2 ms (1.05×), median of per-round ratios ~1.1× (spread 0.96–2.2×);
//! bench `ONLY=long`, main's binary and this one alternating, find vs geo: main 0.48×,
//! 0.56×, 0.46×, this 0.48×, 0.74×, 0.49× (find 32–44 ms main, 28–41 ms this); a
//! second set at load ~6: find main 21.1, 20.6, 21.5 ms, this 20.7, 22.8, 19.8 ms (best
//! 1.04×), geo 10.4–22.6 ms; example binaries best 19.4 → 18.3 ms (1.06×). Still
//! below geo on this row: the remaining ~400 instructions per crossing are the two
//! cross products, the division and the coordinates, which depend on the pair.
//!
//! Session 9 (quiet machine, load about 1, long row only, three runs): find 11.8 / 14.0
//! / 9.0 ms against geo's collect() 10.8–11.0 ms (0.92×, 0.78×, 1.21×); count 1.69–2.51×.
//! One thread: find ~14 ms (scan 7.5, bucket sort ~4.5, points 1.7) against geo's
//! ~10.4 ms. 512 coarse buckets instead of 2048 halve the scatter phase (1.4–1.9 →
//! 0.8–0.9 ms on one thread); in a steady state the allocator reuses the buffers
//! (1,250 minor faults per call), so fresh memory is not the main cost.
//!
//! Session 11 (branch s11-longfind), long random 1e3, one thread, callgrind
//! (`examples/intersect_profile find 1000`, 241 717 crossings): 187M → 152M instructions
//! per call. The axis sweep's pair scan runs on its segments laid out as arrays in sweep
//! order, eight candidates at a time, four orientations against the static bound in one
//! vectorized loop with the verdicts as bit masks (187M → 164M; simulated mispredicts of
//! the scan ~123k → ~74k per call); one insertion sort per coarse bucket instead of a
//! branch on every fine bucket's length (sort mispredicts ~193k → ~100k, +1.3M
//! instructions); the sort's key range from the input's y range instead of a pass over
//! the records (−7M); the crossings of one segment rounded eight at a time with that
//! segment's entry shared by the lanes (−4.4M); the grid's and the sweep's scans as
//! separate instantiations. Wall, load 5.8 (three other helpers building), example
//! binaries alternating, best of 20 per run: one thread 15.9–30.8 → 12.5–18.6 ms
//! (paired ratios 0.56–0.82), two threads 21.3–24.2 → 15.8–18.5 ms. This bench at the
//! same load, three runs: find vs geo collect() 0.94×, 1.20×, 0.95× (not a quiet
//! figure). Short 1e5 (grid path, unchanged code): +4M instructions per call (~2%,
//! inlining differences in `Grid::new` and `Prepared::of`).
//!
//! Session 24, long random 1e3 (`examples/intersect_profile`, one thread, callgrind per
//! call): find 143.6M → 131.3M (the axis sweep's batched scan compiled a second time for
//! AVX2+FMA with the fused rounding inlined; `IntersectionPoint` 56 → 40 bytes), count
//! 108.8M → 78.7M (count uses the same batched filter instead of a branchy test per
//! pair, and its wide instantiation). Wall, one thread, example binaries alternating,
//! best of 15, load 1.5–2.9 (a helper running callgrind): find 14.9 → 14.1 ms (the
//! smaller record), then 13.0–14.2 → 12.4–12.7 ms (the wide scan); count 10.4 →
//! 8.5–8.8 ms. This bench at that load,
//! one thread: count vs geo `count()` 1.35–1.37×, vs the counting O(n²) loop
//! 1.11–1.19×; find vs geo `collect()` 0.69–0.74×, vs the collecting loop 0.56–0.65×.
//! Find is slower here (18–21 ms) than the driver's best at other moments (12.6–14.6
//! ms); run right after each other the two differ by 10–15% (bench 20.9 ms with the
//! timer around the drop, driver 17.5–18.4 ms, load 2.5), without page faults in the
//! bench (0 per call after the first round): the load moved, not the code.
//! With two threads, when the second vCPU runs, find is
//! 7.1–7.6 ms in the driver and 10.4–10.5 ms here (1.14–1.16× geo `collect()`,
//! 1.01–1.03× the collecting loop); when it does not, it runs as one thread.
//!
//! Session 25, long random 1e3, one thread. The gap between this table (find 18–19 ms)
//! and the driver (13–15 ms) is the state the call finds the machine in, not page
//! faults (0 per call here after the first rounds) nor the rayon pool: in the driver,
//! 30 ms of scalar arithmetic before each call (on the calling thread or on the pool's)
//! slows every phase, while a `find` on other segments before it does not. The likely
//! cause is writes into memory that has left the caches: the large scans now put their
//! records straight into bins by y and sort each bin apart (`compgeom::intersect::bins`),
//! and with 490 bins (490 write streams) such work slowed the scan 7.0 → 10.4 ms, with
//! 61 bins only to 7.6–8.2 ms. In the driver after such work: scan 7.6–8.2 ms, sort 3.7–4.1
//! ms (the old scan 5.7 and sort 6.1 ms at rest). This table, load ~1.1 (a helper
//! building): find 15.8 ms against geo `collect()` 13.0 ms, 0.83× (was 0.68–0.76×), the
//! collecting loop 0.73× (was 0.56–0.65×); two threads 0.87× with the second vCPU busy.
//! Short 1e5 find 3.03×, grid 1e4 1.11× (unchanged).
//!
//! Session 26 (quiet machine, load ~1.2). On a pool of at most two threads the large
//! results are now assembled bin by bin on the calling thread after the scan
//! (`assemble_fused`: each bin sorted into a scratch buffer, its points appended to the
//! result while it is in cache, stretches of lone crossings appended by one `extend`;
//! the bins sized by an estimate of their share of the crossings; two fine buckets per
//! record). Long random 1e3, one thread: callgrind per `find` 139.1M → 102.8M; the
//! driver (`examples/intersect_profile find 1000 20`) 10.8–11.2 → 8.2–8.4 ms. Before,
//! with two threads the pool's assembly was slower than one thread's fused one. This
//! table, three full runs each way, ratio = geo / compgeom:
//!
//! | input | threads | count vs geo count() | find vs geo collect() | count vs O(n²) count | find vs O(n²) collect |
//! |---|---:|---|---|---|---|
//! | short random 1e5 | 1 | 5.47–5.71× | 3.49–3.65× | 458–477× | 284–313× |
//! | long random 1e3 | 1 | 1.38× | 1.14–1.19× (9.5–10.1 ms) | 1.15–1.17× | 0.99–1.01× |
//! | 100×100 grid 1e4 | 1 | 1.10–1.13× | 1.14–1.16× | 8.3–8.5× | 8.3–8.6× |
//! | short random 1e5 | 2 | 5.80–7.09× | 3.74–4.79× | 494–584× | 312–402× |
//! | long random 1e3 | 2 | 2.30–2.58× | 1.13–1.40× (7.7–9.7 ms) | 1.92–2.17× | 1.01–1.21× |
//! | 100×100 grid 1e4 | 2 | 1.13–1.37× | 1.49–1.53× | 8.3–10.1× | 10.7–11.0× |
//!
//! Before this session, same machine state (earlier the same evening), one thread: long
//! find 12.0 ms, 0.85× geo `collect()`, 0.75× the collecting loop. What is left: on one
//! thread the long row's `find` ties the collecting O(n²) loop (which neither rounds
//! correctly, merges coincident points nor sorts). Its time (perf, the driver) is now
//! the scan with its rounding (55%), the bin sort (25%) and the points (8%).
//!
//! Session 27, long random 1e3, one thread. The driver now takes this table's input
//! (`examples/intersect_profile find 1000 20 bench-long`): 9.1–9.9 ms there against
//! 10.8–11.3 ms for `find` in this table the same minutes, with 0 page faults per call
//! here. Timed here alone in a loop `find` takes 9.1–9.4 ms; after each of count, geo
//! `count()`, geo `collect()` or a 26 MB vector written and freed it drifts up to 10–11
//! ms. Sampled (perf, 40 calls each, one geo `collect()` before each call here): the scan
//! +7%, the bin sort +40%, the assembly of the points +86% against the driver: writes
//! into memory no cache holds (the 10 MB result above all), which the driver's loop
//! finds warm (it reuses the memory its last result freed, just read by the drop).
//! Tried and not kept: `e_t`'s division in the rounding replaced by a power-of-two bound
//! (`vdivpd` count 22 → 19; driver task-clock +0.8%, no gain: the divisions are not
//! the bottleneck).
//!
//! Session 30, one thread (`RAYON_NUM_THREADS=1`), seven runs of the table on a quiet
//! machine: long random 1e3 find 7.1–7.7 ms against the collecting O(n²) loop's
//! 7.6–8.3 ms (1.03–1.14×) and geo `collect()` 9.2–9.8 ms (1.30–1.37×); count 1.68–1.72×
//! geo `count()`; short 1e5 5.3–5.7× / 6.1–6.6×; grid 1.46–1.48× / 1.35×. Sessions 28
//! and 29 measured 0.86× and 0.99× against the collecting loop on the same code: this
//! row moves ±15% with the machine. Where `find` goes (perf, the driver): the pair
//! scan with its rounding 66%, the bin sort 19%, the points 6%. Tried and not kept: the
//! three divisions of the rounding (`t_hi`, `t_lo`, `e_t`'s bound) as products with one
//! reciprocal of the denominator (timing only, the error bound not redone): 7.2–7.7 ms
//! against 7.1–7.4, no gain, so that lead is closed.
//!
//! Session 33 (quiet machine, load ~1.0), three full runs per thread count, ratio =
//! geo / compgeom, every row above 1:
//!
//! | input | threads | count vs geo count() | find vs geo collect() | count vs O(n²) count | find vs O(n²) collect |
//! |---|---:|---|---|---|---|
//! | short random 1e5 (51 003 points) | 1 | 6.44–6.60× | 4.39–5.31× | 559–568× | 368–443× |
//! | long random 1e3 (251 108 points) | 1 | 1.65–1.66× | 1.25–1.30× (7.7–8.0 ms) | 1.35–1.37× | 1.04–1.08× |
//! | 100×100 grid 1e4 (27 344 points, 916 overlaps) | 1 | 1.30–1.33× | 1.38–1.46× | 9.35–9.45× | 9.40–9.74× |
//! | short random 1e5 | 2 | 7.46–9.34× | 6.51–7.57× | 632–825× | 542–632× |
//! | long random 1e3 | 2 | 1.84–2.84× | 1.32–1.67× | 1.53–2.33× | 1.11–1.38× |
//! | 100×100 grid 1e4 | 2 | 1.51–1.67× | 1.81–1.94× | 10.7–11.9× | 12.0–12.8× |
//!
//! Growth of the dense case (`COMPGEOM_BENCH_LONG_N`, count against geo `count()`, one
//! thread): n = 1e3 5.5 ms (1.64×), n = 1e4 (25.1M points) 0.567 s (1.73×); two threads
//! at 1e4 0.293 s (3.34×). Small inputs are where compgeom is weakest: `--quick` (long
//! n = 100, 2 410 points) find 0.69× geo `collect()`, because a call there pays about 40
//! page faults and a heap trim (glibc gives the scratch buffers back each call; perf: 35%
//! of the driver's time at n = 200 is in page faults), which a 0.1 ms call cannot absorb.

use crate::util::{best_of, Rng};
use compgeom::intersect::{count_intersections, find_intersections, sweep_intersections};
use compgeom::{Point2, Segment2};
use geo::algorithm::sweep::Intersections;
use geo::line_intersection::{line_intersection, LineIntersection};
use geo::{coord, Line};
use std::hint::black_box;

/// Uniform integer in `lo..=hi`.
fn int(rng: &mut Rng, lo: i64, hi: i64) -> i64 {
    lo + (rng.next_u64() % (hi - lo + 1) as u64) as i64
}

/// `n` short segments in the unit square (length below 0.008, random direction):
/// about linearly many crossings.
fn short_segments(rng: &mut Rng, n: usize) -> Vec<Segment2> {
    (0..n)
        .map(|_| {
            let a = Point2::new(rng.unit(), rng.unit());
            let (len, angle) = (0.008 * rng.unit(), std::f64::consts::TAU * rng.unit());
            Segment2::new(
                a,
                Point2::new(a.x + len * angle.cos(), a.y + len * angle.sin()),
            )
        })
        .collect()
}

/// `n` segments from the left side of the unit square to the right side: each pair
/// crosses with probability 1/2, about n²/4 crossings.
fn long_segments(rng: &mut Rng, n: usize) -> Vec<Segment2> {
    (0..n)
        .map(|_| Segment2::new(Point2::new(0.0, rng.unit()), Point2::new(1.0, rng.unit())))
        .collect()
}

/// `n` short segments with endpoints on the 100×100 integer grid (each end within 4
/// units of the other): shared endpoints, collinear overlaps, duplicates, zero-length
/// segments, many segments through one point.
fn grid_segments(rng: &mut Rng, n: usize) -> Vec<Segment2> {
    (0..n)
        .map(|_| {
            let (x, y) = (int(rng, 0, 100), int(rng, 0, 100));
            let (u, v) = (
                (x + int(rng, -4, 4)).clamp(0, 100),
                (y + int(rng, -4, 4)).clamp(0, 100),
            );
            Segment2::new(
                Point2::new(x as f64, y as f64),
                Point2::new(u as f64, v as f64),
            )
        })
        .collect()
}

fn to_geo(segs: &[Segment2]) -> Vec<Line<f64>> {
    segs.iter()
        .map(|s| Line::new(coord! { x: s.a.x, y: s.a.y }, coord! { x: s.b.x, y: s.b.y }))
        .collect()
}

fn geo_sweep_pairs(lines: &[Line<f64>]) -> usize {
    Intersections::from_iter(lines.iter()).count()
}

fn geo_sweep_collect(lines: &[Line<f64>]) -> Vec<(&Line<f64>, &Line<f64>, LineIntersection<f64>)> {
    Intersections::from_iter(lines.iter()).collect()
}

/// The boxes `[min x, max x, min y, max y]` of `lines`, for the O(n²) loops' box test.
fn line_boxes(lines: &[Line<f64>]) -> Vec<[f64; 4]> {
    lines
        .iter()
        .map(|l| {
            [
                l.start.x.min(l.end.x),
                l.start.x.max(l.end.x),
                l.start.y.min(l.end.y),
                l.start.y.max(l.end.y),
            ]
        })
        .collect()
}

/// Calls `meet(i, j, how)` for every pair `i < j` of `lines` that meets, by a plain
/// O(n²) loop: a box test, then geo's `line_intersection`.
#[inline]
fn geo_brute_each(lines: &[Line<f64>], mut meet: impl FnMut(usize, usize, LineIntersection<f64>)) {
    let boxes = line_boxes(lines);
    for i in 0..lines.len() {
        for j in i + 1..lines.len() {
            let (a, b) = (&boxes[i], &boxes[j]);
            if a[0] > b[1] || b[0] > a[1] || a[2] > b[3] || b[2] > a[3] {
                continue;
            }
            if let Some(how) = line_intersection(lines[i], lines[j]) {
                meet(i, j, how);
            }
        }
    }
}

/// The O(n²) loop keeping nothing: the number of meeting pairs.
fn geo_brute_pairs(lines: &[Line<f64>]) -> usize {
    let mut count = 0;
    geo_brute_each(lines, |_, _, _| count += 1);
    count
}

/// The O(n²) loop keeping its answer: one `(i, j, intersection)` per meeting pair.
fn geo_brute_collect(lines: &[Line<f64>]) -> Vec<(usize, usize, LineIntersection<f64>)> {
    let mut found = Vec::new();
    geo_brute_each(lines, |i, j, how| found.push((i, j, how)));
    found
}

fn case(name: &str, segs: &[Segment2], brute_runs: usize) -> Result<(), String> {
    let lines = to_geo(segs);
    // Answers, once, outside the clock.
    let ours = find_intersections(segs).map_err(|e| e.to_string())?;
    let geo_pairs = geo_sweep_pairs(&lines);
    let pairs = ours.pair_count();
    if pairs != geo_pairs {
        return Err(format!(
            "{name}: {pairs} meeting pairs, geo finds {geo_pairs}"
        ));
    }
    if sweep_intersections(segs)
        .map_err(|e| e.to_string())?
        .pair_count()
        != pairs
    {
        return Err(format!("{name}: the sweep and the default disagree"));
    }
    let count = count_intersections(segs).map_err(|e| e.to_string())?;
    if (count.points, count.overlaps, count.pairs)
        != (ours.points.len(), ours.overlaps.len(), pairs)
    {
        return Err(format!("{name}: the count disagrees with the answer"));
    }
    // Interleaved rounds, best of each: load changes hit every contestant alike.
    let (mut t_ours, mut t_count, mut t_geo, mut t_collect) =
        (f64::MAX, f64::MAX, f64::MAX, f64::MAX);
    for _ in 0..RUNS {
        let best = |t: &mut f64, d: std::time::Duration| *t = t.min(d.as_secs_f64());
        best(
            &mut t_ours,
            best_of(1, || find_intersections(black_box(segs)).unwrap()),
        );
        best(
            &mut t_count,
            best_of(1, || count_intersections(black_box(segs)).unwrap()),
        );
        best(
            &mut t_geo,
            best_of(1, || geo_sweep_pairs(black_box(&lines))),
        );
        best(
            &mut t_collect,
            best_of(1, || geo_sweep_collect(black_box(&lines))),
        );
    }
    let t_sweep = best_of(3, || sweep_intersections(black_box(segs)).unwrap()).as_secs_f64();
    // The O(n²) loops, the counting one against compgeom's count and the collecting
    // one against its find (each side keeping, or not keeping, its answer).
    let brute = if brute_runs == 0 {
        "| skipped | | skipped | |".to_string()
    } else {
        let (mut t_brute, mut t_brute_collect) = (f64::MAX, f64::MAX);
        for _ in 0..brute_runs {
            let t = best_of(1, || geo_brute_pairs(black_box(&lines)));
            t_brute = t_brute.min(t.as_secs_f64());
            let t = best_of(1, || geo_brute_collect(black_box(&lines)));
            t_brute_collect = t_brute_collect.min(t.as_secs_f64());
        }
        format!(
            "| {t_brute:.4} | {:.2}× | {t_brute_collect:.4} | {:.2}× |",
            t_brute / t_count,
            t_brute_collect / t_ours
        )
    };
    println!(
        "| {name} | {} | {} | {} | {pairs} | {t_count:.4} | {t_geo:.4} | **{:.2}×** | {t_ours:.4} | {t_collect:.4} | **{:.2}×** | {t_sweep:.4} {brute}",
        segs.len(),
        ours.points.len(),
        ours.overlaps.len(),
        t_geo / t_count,
        t_collect / t_ours,
    );
    Ok(())
}

/// Timed rounds per contestant.
const RUNS: usize = 5;

/// `COMPGEOM_BENCH_LONG_N=n`: only the counts on `n` long random segments (about n²/4
/// crossings), compgeom's `count_intersections` against geo's `count()`, alternating,
/// best of three each: the growth of the dense case without materialising n²/4 points.
fn count_long_only(n: usize) -> Result<(), String> {
    let mut rng = Rng::new(0x5eed_0003);
    let segs = long_segments(&mut rng, n);
    let lines = to_geo(&segs);
    let count = count_intersections(&segs).map_err(|e| e.to_string())?;
    let geo_pairs = geo_sweep_pairs(&lines);
    if count.pairs != geo_pairs {
        return Err(format!(
            "{} meeting pairs, geo finds {geo_pairs}",
            count.pairs
        ));
    }
    let (mut t_count, mut t_geo) = (f64::MAX, f64::MAX);
    for _ in 0..3 {
        let t = best_of(1, || count_intersections(black_box(&segs)).unwrap());
        t_count = t_count.min(t.as_secs_f64());
        let t = best_of(1, || geo_sweep_pairs(black_box(&lines)));
        t_geo = t_geo.min(t.as_secs_f64());
    }
    println!("| input | n | points | compgeom count s | geo count() s | geo / compgeom |");
    println!("|---|---:|---:|---:|---:|---:|");
    println!(
        "| long random | {n} | {} | {t_count:.4} | {t_geo:.4} | **{:.2}×** |",
        count.points,
        t_geo / t_count
    );
    Ok(())
}

/// Run the group and print a Markdown table. `quick` uses inputs ten times smaller.
pub fn run(quick: bool) -> Result<(), String> {
    if let Some(n) = std::env::var("COMPGEOM_BENCH_LONG_N")
        .ok()
        .and_then(|v| v.parse().ok())
    {
        return count_long_only(n);
    }
    let mut rng = Rng::new(0x5eed_0002);
    let k = if quick { 10 } else { 1 };
    println!(
        "## intersect: segment intersection (best of {RUNS}, interleaved; the O(n²) loop once at n = 1e5)\n"
    );
    println!(
        "| input | n | intersection points | overlaps | meeting pairs (= geo's) | compgeom count s | geo sweep count() s | geo count / compgeom count | compgeom find s | geo sweep collect() s | geo collect / compgeom find | compgeom sweep s | geo O(n²) count s | O(n²) count / compgeom count | geo O(n²) collect s | O(n²) collect / compgeom find |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    // `COMPGEOM_BENCH_ONLY=short|long|grid` runs one input (the others are still
    // generated, so that every input is the same as in a full run).
    let only = std::env::var("COMPGEOM_BENCH_ONLY").unwrap_or_default();
    let wanted = |name: &str| only.is_empty() || name.starts_with(only.as_str());
    let short = short_segments(&mut rng, 100_000 / k);
    if wanted("short") {
        case("short random", &short, 1)?;
    }
    let long = long_segments(&mut rng, 1_000 / k);
    if wanted("long") {
        case("long random", &long, 3)?;
    }
    let grid = grid_segments(&mut rng, 10_000 / k);
    if wanted("grid") {
        case("100×100 grid", &grid, 3)?;
    }
    Ok(())
}
