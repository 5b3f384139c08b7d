-- arg_scale: two-stage search for large catalogues. arg_global(descr) is a compact descriptor
-- (a cube point) that a GiST index orders by the taxicab distance <#>; the nearest candidates
-- are then ranked exactly by <~>. arg_knn does both in one call. (The arg extension requires
-- cube: CREATE EXTENSION arg CASCADE installs it; pg_regress loads it for these tests.)

CREATE EXTENSION arg;

CREATE TABLE museum_objects (
  id     int PRIMARY KEY,
  museum text NOT NULL,
  class  text NOT NULL,
  descr  arg
);
INSERT INTO museum_objects
SELECT i, 'M' || (i % 4 + 1), c.class, arg_build(arg_generate_model(c.class, i / 9, 16))
FROM generate_series(0, 35) AS i,
     LATERAL (SELECT (ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table',
                            'chair', 'octopus'])[i % 9 + 1] AS class) AS c;
INSERT INTO museum_objects VALUES (100, 'M1', 'not scanned', NULL);
ANALYZE museum_objects;

-- The descriptor: 92 values, the same as a float8[] and as a cube point; a model is at
-- distance 0 from itself; NULL in, NULL out.
SELECT array_length(arg_global_vector(descr), 1) AS values,
       cube_dim(arg_global(descr)) AS cube_dims,
       arg_global(descr) = cube(arg_global_vector(descr)) AS same_values,
       arg_global(descr) <#> arg_global(descr) AS self_distance
FROM museum_objects WHERE id = 0;
SELECT count(*) AS all_equal FROM museum_objects
WHERE arg_global(descr) = cube(arg_global_vector(descr));
SELECT arg_global(descr) IS NULL AS null_gives_null FROM museum_objects WHERE id = 100;
-- Every value finite; all but the log eigenvalues (values 71 to 80) are sums of non-negative
-- features.
SELECT bool_and(x > '-Infinity' AND x < 'Infinity') AS all_finite,
       bool_and(x >= 0) FILTER (WHERE k NOT BETWEEN 71 AND 80) AS non_negative_but_eigenvalues
FROM museum_objects, unnest(arg_global_vector(descr)) WITH ORDINALITY AS v(x, k);

-- Nearer by <#> means more alike by SIM: the nearest candidates of a vase are vases.
SELECT o.id, o.class
FROM museum_objects o, museum_objects q
WHERE q.id = 0 AND o.id <> 0
ORDER BY arg_global(o.descr) <#> arg_global(q.descr), o.id LIMIT 2;

-- A GiST index on the descriptor answers the candidates query in distance order.
CREATE INDEX museum_objects_global ON museum_objects USING gist (arg_global(descr));
SET enable_seqscan = off;
SET plan_cache_mode = force_generic_plan;  -- plans for any query model, as from a client
PREPARE candidates(arg, int) AS
  SELECT id FROM museum_objects ORDER BY arg_global(descr) <#> arg_global($1) LIMIT $2;
EXPLAIN (COSTS OFF) EXECUTE candidates(NULL, 10);
SELECT descr AS q FROM museum_objects WHERE id = 0 \gset
SELECT array_agg(id) = (SELECT array_agg(id ORDER BY d, id) FROM (
         SELECT id, arg_global(descr) <#> arg_global(:'q') AS d FROM museum_objects
         WHERE descr IS NOT NULL ORDER BY d LIMIT 10) s) AS index_order_is_distance_order
FROM (SELECT id FROM museum_objects
      ORDER BY arg_global(descr) <#> arg_global(:'q'), id LIMIT 10) i;

RESET enable_seqscan;

-- The two-stage query as a CTE: candidates from the index, ranked exactly. With as many
-- candidates as rows it is brute force; with fewer it is an approximation that is usually
-- right (docs/BENCHMARKS.md "Scale" measures how often).
CREATE TABLE brute AS
SELECT id, descr <~> :'q' AS sim FROM museum_objects
WHERE descr IS NOT NULL ORDER BY descr <~> :'q', id LIMIT 5;
SELECT count(*) AS same_as_brute_force
FROM (WITH c AS MATERIALIZED (
        SELECT id, descr FROM museum_objects
        ORDER BY arg_global(descr) <#> arg_global(:'q') LIMIT 36)
      SELECT id, descr <~> :'q' AS sim FROM c ORDER BY sim, id LIMIT 5) two_stage
JOIN brute USING (id, sim);

-- arg_knn: the same in one call, rows of the table and their SIM, best first.
SELECT (o).id, (o).class, round(sim::numeric, 6) = round((SELECT sim FROM brute WHERE id = (o).id)::numeric, 6) AS sim_as_brute
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, candidates => 36) AS k(o, sim);
SELECT count(*) AS rows_with_default_candidates, min(sim) AS best
FROM arg_knn(NULL::museum_objects, 'descr', :'q');

SHOW enable_seqscan;  -- arg_knn turns it off for its own query only

-- A stored descriptor column: the first stage scans it instead of computing arg_global(descr)
-- for every row (faster than GiST in 92 dimensions, where boxes overlap; docs/BENCHMARKS.md).
ALTER TABLE museum_objects ADD COLUMN glob cube GENERATED ALWAYS AS (arg_global(descr)) STORED;
SELECT count(*) AS same_answer_as_the_index
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 10, descriptor => 'glob') AS a(o, sim)
JOIN arg_knn(NULL::museum_objects, 'descr', :'q', 5, 10) AS b(o, sim)
  ON (a.o).id = (b.o).id AND a.sim = b.sim;

-- The second stage: a stored sketch (SIM's panorama and spectrum as the value holds them, and
-- the descriptor's graph blocks), out of line and uncompressed, as arg.
ALTER TABLE museum_objects ADD COLUMN sk arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED;
SELECT attstorage AS sketch_storage FROM pg_attribute
WHERE attrelid = 'museum_objects'::regclass AND attname = 'sk';
SELECT count(*) AS sketches, min(octet_length(sk::text)) > 2000 AS text_over_2000_chars,
       bool_and(sk::text = sk::text::arg_sketch::text) AS text_round_trips,
       bool_and(arg_sketch_distance(sk, sk) = 0) AS zero_to_itself,
       bool_and(arg_sketch_distance(sk, arg_sketch(:'q'::arg)) = arg_sketch_distance(arg_sketch(:'q'::arg), sk))
         AS symmetric
FROM museum_objects WHERE sk IS NOT NULL;
-- Over every pair in one statement (the function keeps each argument's last sketch read):
-- symmetric, and as many distinct distances as pairs of different models.
SELECT bool_and(arg_sketch_distance(a.sk, b.sk) = arg_sketch_distance(b.sk, a.sk))
         AS symmetric_over_all_pairs,
       count(DISTINCT arg_sketch_distance(a.sk, b.sk)) FILTER (WHERE a.id < b.id) AS distinct_distances
FROM museum_objects a, museum_objects b WHERE a.sk IS NOT NULL AND b.sk IS NOT NULL;
-- Nearer by the sketch means more alike by SIM: the nearest of a vase are vases.
SELECT o.id, o.class FROM museum_objects o
WHERE o.id <> 0 AND o.sk IS NOT NULL
ORDER BY arg_sketch_distance(o.sk, arg_sketch(:'q'::arg)), o.id LIMIT 2;
-- Its weights are SIM's: the graph alone leaves only the graph blocks, which differ.
SELECT arg_sketch_distance(a.sk, b.sk, 'graph=1 panorama=0 spectrum=0')
       <> arg_sketch_distance(a.sk, b.sk) AS weights_count
FROM museum_objects a, museum_objects b WHERE a.id = 0 AND b.id = 9;
-- Three stages in one call: with every row a candidate and on the shortlist, brute force.
SELECT count(*) AS three_stages_as_brute_force
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 36, descriptor => 'glob', sketch => 'sk',
             shortlist => 36) AS k(o, sim)
JOIN brute ON brute.id = (k.o).id AND brute.sim = k.sim;
-- A shortlist of 10 of the 36 rows still holds SIM's five nearest of this vase.
SELECT count(*) AS five_nearest_from_a_shortlist_of_10
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 36, descriptor => 'glob', sketch => 'sk',
             shortlist => 10) AS k(o, sim)
JOIN brute ON brute.id = (k.o).id AND brute.sim = k.sim;
-- The first stage from the GiST index instead of the stored column: the same answer.
SELECT count(*) AS gist_first_stage_same_answer
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 36, sketch => 'sk', shortlist => 10) AS a(o, sim)
JOIN arg_knn(NULL::museum_objects, 'descr', :'q', 5, 36, descriptor => 'glob', sketch => 'sk',
             shortlist => 10) AS b(o, sim) ON (a.o).id = (b.o).id AND a.sim = b.sim;
-- A table with an inheritance child: the child's rows rank (here a copy of the query, SIM 0)
-- and a filter still holds for them (row addresses repeat across parent and child, so the
-- first stage sorts rows there, not addresses).
CREATE TABLE shelf (id int, museum text, descr arg,
                    glob cube GENERATED ALWAYS AS (arg_global(descr)) STORED,
                    sk arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED);
INSERT INTO shelf (id, museum, descr) SELECT id, museum, descr FROM museum_objects;
CREATE TABLE shelf_annex () INHERITS (shelf);
INSERT INTO shelf_annex (id, museum, descr) SELECT 1000, 'M9', descr FROM museum_objects WHERE id = 0;
SELECT (o).id, (o).museum, sim
FROM arg_knn(NULL::shelf, 'descr', :'q', 2, descriptor => 'glob', sketch => 'sk') AS k(o, sim);
SELECT count(*) AS rows, bool_and((o).museum = 'M2') AS all_in_m2
FROM arg_knn(NULL::shelf, 'descr', :'q', 5, 36, '{"museum": "M2"}', 'glob', 'sk', 10) AS k(o, sim);
DROP TABLE shelf CASCADE;
\set VERBOSITY terse
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', shortlist => 10);
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', sketch => 'glob');
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', sketch => 'sk', shortlist => 0);
SELECT 'sketch1:QUJD'::arg_sketch;
SELECT 'arg1:QUJD'::arg_sketch;
SELECT overlay(sk::text placing 'A' from 9 for 1)::arg_sketch FROM museum_objects WHERE id = 0;
\set VERBOSITY default

-- Under a filter it still returns k rows (when that many match), all of them matching.
SELECT count(*) AS rows, bool_and((o).museum = 'M2') AS all_in_m2
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 5, '{"museum": "M2"}') AS k(o, sim);
SELECT count(*) AS one_vase_in_m3
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 5, '{"museum": "M3", "class": "vase"}');
SELECT (o).id AS unscanned_rows_never_rank
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 5, '{"class": "not scanned"}') AS k(o, sim);

-- A filter is data, never SQL: keys are quoted as identifiers, values as literals.
\set VERBOSITY terse
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 5,
                             '{"museum": "M2'' OR true --"}');
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 5,
                             '{"museum = museum OR true": "M2"}');
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', 5, 5, '["museum", "M2"]');
SELECT count(*) FROM arg_knn(NULL::int, 'descr', :'q');
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'class', :'q');
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', descriptor => 'descr');
SELECT count(*) FROM arg_knn(NULL::museum_objects, 'descr', :'q', 0);
SELECT count(*) AS still_there FROM museum_objects;

-- A role that may create objects in public cannot plant one that arg_knn calls: arg_knn's
-- search_path is pg_catalog, pg_temp and it names arg's and cube's objects with their schema.
-- The planted format(text, name) is a closer match than the built-in format(text, VARIADIC
-- "any") wherever public is searched (shown last), and arg_knn calls format with a name.
CREATE ROLE arg_planter;
GRANT CREATE ON SCHEMA public TO arg_planter;
SET ROLE arg_planter;
CREATE FUNCTION public.format(text, name) RETURNS text LANGUAGE plpgsql
  AS $$ BEGIN RAISE EXCEPTION 'the planted format ran as %', current_user; END $$;
RESET ROLE;
SELECT count(*) AS knn_rows_without_the_plant
FROM arg_knn(NULL::museum_objects, 'descr', :'q', 3, descriptor => 'glob');
SET search_path = public, pg_catalog;
SELECT format('%I', 'descr'::name);
RESET search_path;
DROP FUNCTION public.format(text, name);
REVOKE CREATE ON SCHEMA public FROM arg_planter;
DROP ROLE arg_planter;
\set VERBOSITY default

-- With btree_gist, one GiST index holds the filter column and the descriptor, so a selective
-- filter is applied inside the index scan.
CREATE EXTENSION btree_gist;
CREATE INDEX museum_objects_museum_global ON museum_objects
  USING gist (museum, arg_global(descr));
PREPARE in_museum(text, arg) AS
  SELECT id FROM museum_objects WHERE museum = $1
  ORDER BY arg_global(descr) <#> arg_global($2) LIMIT 10;
SET enable_seqscan = off;
SET enable_bitmapscan = off;  -- on a table this small the planner would rather sort 9 rows
EXPLAIN (COSTS OFF) EXECUTE in_museum('M2', NULL);
RESET enable_seqscan;
RESET enable_bitmapscan;

-- The index expression needs no search_path (pg_restore runs with an empty one).
SET search_path = '';
CREATE INDEX museum_objects_global_again ON public.museum_objects
  USING gist (public.arg_global(descr));
RESET search_path;

RESET plan_cache_mode;
DEALLOCATE candidates;
DEALLOCATE in_museum;
DROP TABLE museum_objects, brute;
DROP EXTENSION btree_gist;
DROP EXTENSION arg;
