-- arg_ivf: an approximate index of sketches, an inverted file. Its cells are centred on sketches
-- of a sample of the rows and each row is filed under its nearest centre; ORDER BY sk <~> query
-- reads the lists of the arg.ivf_probes cells nearest to the query. With as many probes as
-- cells it returns what ordering every row by the sketch distance returns.

CREATE EXTENSION arg;

CREATE TABLE shapes (
  id    int PRIMARY KEY,
  class text NOT NULL,
  descr arg,
  sk    arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED
);
INSERT INTO shapes (id, class, descr)
SELECT i, c.class, arg_build(arg_generate_model(c.class, i / 9, 16))
FROM generate_series(0, 44) AS i,
     LATERAL (SELECT (ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table',
                            'chair', 'octopus'])[i % 9 + 1] AS class) AS c;
INSERT INTO shapes (id, class, descr) VALUES (100, 'no model', NULL);
ANALYZE shapes;
SELECT sk AS q FROM shapes WHERE id = 0 \gset

-- <~> between sketches is arg_sketch_distance with the default weights.
SELECT bool_and(a.sk <~> b.sk = arg_sketch_distance(a.sk, b.sk)) AS operator_is_the_distance,
       bool_and(a.sk <~> b.sk = b.sk <~> a.sk) AS symmetric
FROM shapes a, shapes b WHERE a.id < 12 AND b.id < 12;

CREATE INDEX shapes_sk ON shapes USING arg_ivf (sk) WITH (lists = 5);
SELECT amvalidate(c.oid) AS opclass_valid FROM pg_opclass c WHERE c.opcname = 'arg_sketch_ops';
SET enable_seqscan = off;
SET plan_cache_mode = force_generic_plan;  -- plans for any query sketch, as from a client
PREPARE nearest(arg_sketch, int) AS SELECT id FROM shapes ORDER BY sk <~> $1 LIMIT $2;
EXPLAIN (COSTS OFF) EXECUTE nearest(NULL, 5);
-- Without a LIMIT a query asks for every row in order, which reading some cells cannot give:
-- the index is not used, nor for two distances at once.
PREPARE every_row(arg_sketch) AS SELECT id FROM shapes ORDER BY sk <~> $1;
EXPLAIN (COSTS OFF) EXECUTE every_row(NULL);
PREPARE two_keys(arg_sketch, arg_sketch) AS
  SELECT id FROM shapes ORDER BY sk <~> $1, sk <~> $2 LIMIT 5;
EXPLAIN (COSTS OFF) EXECUTE two_keys(NULL, NULL);
-- LIMIT ALL asks for every row too; a window over every row (count(*) OVER ()) reads them all
-- before the LIMIT.
PREPARE limit_all(arg_sketch) AS SELECT id FROM shapes ORDER BY sk <~> $1 LIMIT ALL;
EXPLAIN (COSTS OFF) EXECUTE limit_all(NULL);
PREPARE with_total(arg_sketch, int) AS
  SELECT id, count(*) OVER () AS total FROM shapes ORDER BY sk <~> $1 LIMIT $2;
EXPLAIN (COSTS OFF) EXECUTE with_total(NULL, 5);
DEALLOCATE every_row;
DEALLOCATE two_keys;
DEALLOCATE limit_all;
DEALLOCATE with_total;

-- Every probe: every row, nearest first, the same order and distances as sorting them all
-- (ties, if any, by row address, which is id order here); the NULL sketch is not indexed.
SET arg.ivf_probes = 5;
SELECT count(*) AS queries,
       bool_and(i.ids = e.ids) AS same_order_as_sorting_every_row,
       bool_and(cardinality(i.ids) = 45) AS every_indexed_row
FROM shapes q,
     LATERAL (SELECT array_agg(id) AS ids
              FROM (SELECT id FROM shapes ORDER BY sk <~> q.sk LIMIT 50) s) i,
     LATERAL (SELECT array_agg(id ORDER BY arg_sketch_distance(sk, q.sk), id) AS ids
              FROM shapes WHERE sk IS NOT NULL) e
WHERE q.sk IS NOT NULL;

-- One probe: a row's own cell is the nearest to it, so every row finds itself first, and only
-- that cell's rows come back.
SET arg.ivf_probes = 1;
SELECT bool_and(first = q.id) AS finds_itself_first, max(n) < 45 AS reads_one_cell
FROM shapes q,
     LATERAL (SELECT (array_agg(id))[1] AS first, count(*) AS n
              FROM (SELECT id FROM shapes ORDER BY sk <~> q.sk LIMIT 50) s) i
WHERE q.sk IS NOT NULL;

-- Two probes of five: most of each row's five nearest.
SET arg.ivf_probes = 2;
SELECT avg(cardinality(ARRAY(SELECT unnest(i.ids) INTERSECT SELECT unnest(e.ids))) / 5.0) >= 0.8
         AS recall_of_five_at_least_80_percent
FROM shapes q,
     LATERAL (SELECT array_agg(id) AS ids
              FROM (SELECT id FROM shapes ORDER BY sk <~> q.sk LIMIT 5) s) i,
     LATERAL (SELECT array_agg(id) AS ids
              FROM (SELECT id FROM shapes WHERE sk IS NOT NULL
                    ORDER BY arg_sketch_distance(sk, q.sk), id LIMIT 5) s) e
WHERE q.sk IS NOT NULL;

-- The search in three stages without a descriptor: the index's 20 nearest sketches, ranked by
-- SIM, give brute force's five nearest.
SET arg.ivf_probes = 3;
SELECT descr AS qa FROM shapes WHERE id = 0 \gset
SELECT array_agg(id) = (SELECT array_agg(id) FROM (SELECT id FROM shapes WHERE descr IS NOT NULL
                                                   ORDER BY descr <~> :'qa', id LIMIT 5) b)
         AS three_stages_equal_brute_force
FROM (SELECT id FROM (SELECT id, descr FROM shapes ORDER BY sk <~> arg_sketch(:'qa'::arg) LIMIT 20) c
      ORDER BY descr <~> :'qa', id LIMIT 5) s;

-- arg_knn takes its shortlist from the index when the sketch column has one and neither a
-- filter nor a descriptor column is given: the same rows as the query above. With one probe
-- and more rows asked for than the query's cell holds, every other row is ranked too: still k
-- rows. With a filter the candidates come from the descriptor: every vase.
SELECT array_agg((k.obj).id ORDER BY k.sim, (k.obj).id)
         = (SELECT array_agg(id) FROM (
              SELECT id FROM (SELECT id, descr FROM shapes
                              ORDER BY sk <~> arg_sketch(:'qa'::arg) LIMIT 20) c
              ORDER BY descr <~> :'qa', id LIMIT 5) s) AS knn_same_as_index_query
FROM arg_knn(NULL::shapes, 'descr', :'qa', 5, sketch => 'sk', shortlist => 20) AS k;
SET arg.ivf_probes = 1;
SELECT (SELECT count(*) FROM (SELECT id FROM shapes
                              ORDER BY sk <~> arg_sketch(:'qa'::arg) LIMIT 45) s) < 45
         AS the_index_reads_one_cell,
       count(*) AS knn_rows,
       array_agg((k.obj).id ORDER BY k.sim, (k.obj).id)
         = (SELECT array_agg(id ORDER BY descr <~> :'qa', id) FROM shapes WHERE descr IS NOT NULL)
         AS ranked_as_brute_force
FROM arg_knn(NULL::shapes, 'descr', :'qa', 45, sketch => 'sk', shortlist => 45) AS k;
SELECT count(*) AS vases, array_agg(DISTINCT (k.obj).class) AS classes
FROM arg_knn(NULL::shapes, 'descr', :'qa', 45, filter => '{"class": "vase"}', sketch => 'sk',
             shortlist => 45) AS k;
-- A partitioned table with the index on it: arg_knn through the partitions' indexes (every
-- cell probed, every row on the shortlist: brute force's answer).
CREATE TABLE parts (id int, class text, descr arg, sk arg_sketch) PARTITION BY LIST (class);
CREATE TABLE parts_round PARTITION OF parts FOR VALUES IN ('vase', 'cup', 'amphora', 'torus');
CREATE TABLE parts_other PARTITION OF parts DEFAULT;
INSERT INTO parts SELECT id, class, descr, sk FROM shapes;
CREATE INDEX parts_sk ON parts USING arg_ivf (sk) WITH (lists = 2);
SET arg.ivf_probes = 2;
SELECT array_agg((k.obj).id ORDER BY k.sim, (k.obj).id)
         = (SELECT array_agg(id) FROM (SELECT id FROM shapes WHERE descr IS NOT NULL
                                       ORDER BY descr <~> :'qa', id LIMIT 5) b)
         AS partitioned_as_brute_force
FROM arg_knn(NULL::parts, 'descr', :'qa', 5, sketch => 'sk', shortlist => 45) AS k;
DROP TABLE parts;
SET arg.ivf_probes = 3;

-- A NULL query has no nearest: the index returns every row it holds (not the one with a NULL
-- sketch, which it does not hold).
PREPARE nearest_count(arg_sketch) AS
  SELECT count(*) AS rows FROM (SELECT id FROM shapes ORDER BY sk <~> $1 LIMIT 100) s;
EXPLAIN (COSTS OFF) EXECUTE nearest_count(NULL);
EXECUTE nearest_count(NULL);

-- Rows inserted after the build join their nearest cell; updated rows move; deleted rows leave
-- with VACUUM.
SET arg.ivf_probes = 5;
INSERT INTO shapes (id, class, descr)
SELECT 45 + i, 'cup', arg_build(arg_generate_model('cup', 10 + i, 16)) FROM generate_series(0, 5) AS i;
UPDATE shapes SET descr = arg_build(arg_generate_model('torus', 20, 16)) WHERE id = 1;
SELECT sk AS q1 FROM shapes WHERE id = 1 \gset
SELECT (SELECT id FROM shapes ORDER BY sk <~> :'q1' LIMIT 1) AS updated_row_first,
       (SELECT count(*) FROM (SELECT id FROM shapes ORDER BY sk <~> :'q' LIMIT 100) s) AS rows,
       (SELECT count(*) FROM (SELECT id FROM shapes ORDER BY sk <~> :'q' LIMIT 100) s
        WHERE id >= 45) AS inserted_found;
DELETE FROM shapes WHERE id >= 45;
VACUUM shapes;
SELECT count(*) AS rows_after_vacuum
FROM (SELECT id FROM shapes ORDER BY sk <~> :'q' LIMIT 100) s;
SELECT array_agg(id) = (SELECT array_agg(id ORDER BY arg_sketch_distance(sk, :'q'), id)
                        FROM shapes WHERE sk IS NOT NULL) AS still_exact_with_every_probe
FROM (SELECT id FROM shapes ORDER BY sk <~> :'q' LIMIT 100) s;
REINDEX INDEX shapes_sk;
SELECT count(*) AS rows_after_reindex FROM (SELECT id FROM shapes ORDER BY sk <~> :'q' LIMIT 100) s;
-- Rebuilt with other cells in the same session (whose backend kept the old centres): searched
-- by the new ones.
ALTER INDEX shapes_sk SET (lists = 3);
REINDEX INDEX shapes_sk;
SET arg.ivf_probes = 1;
SELECT bool_and(first = q.id) AS finds_itself_first_in_three_cells
FROM shapes q,
     LATERAL (SELECT id AS first FROM shapes ORDER BY sk <~> q.sk LIMIT 1) i
WHERE q.sk IS NOT NULL;
SET arg.ivf_probes = 3;
SELECT array_agg(id) = (SELECT array_agg(id ORDER BY arg_sketch_distance(sk, :'q'), id)
                        FROM shapes WHERE sk IS NOT NULL) AS exact_with_every_probe
FROM (SELECT id FROM shapes ORDER BY sk <~> :'q' LIMIT 100) s;

-- An index built on an empty table has one cell, which every row joins (REINDEX once the table
-- is loaded); an unlogged table's index too. More lists than rows: a cell a row.
CREATE UNLOGGED TABLE later (id int, sk arg_sketch);
CREATE INDEX later_sk ON later USING arg_ivf (sk);
INSERT INTO later SELECT id, sk FROM shapes;
SELECT array_agg(id) = (SELECT array_agg(id ORDER BY arg_sketch_distance(sk, :'q'), id)
                        FROM later WHERE sk IS NOT NULL) AS one_cell_exact
FROM (SELECT id FROM later ORDER BY sk <~> :'q' LIMIT 100) s;
CREATE INDEX many_lists ON later USING arg_ivf (sk) WITH (lists = 1000);
SET arg.ivf_probes = 1;
SELECT count(*) AS one_probe_one_row FROM (SELECT id FROM later ORDER BY sk <~> :'q' LIMIT 100) s;
DROP INDEX many_lists;

-- Errors.
CREATE INDEX ON shapes USING arg_ivf (sk) WITH (lists = -1);
CREATE INDEX ON shapes USING arg_ivf (sk) WITH (lists = 5000);
CREATE INDEX ON shapes USING arg_ivf (class);
CREATE INDEX ON shapes USING arg_ivf (sk, id);
SET arg.ivf_probes = 0;

DEALLOCATE nearest;
DEALLOCATE nearest_count;
RESET arg.ivf_probes;
RESET enable_seqscan;
RESET plan_cache_mode;
DROP TABLE shapes, later;
DROP EXTENSION arg;
