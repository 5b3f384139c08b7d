-- An arg_ivf index on an arg column itself: one CREATE INDEX, and ORDER BY descr <~> q LIMIT k
-- takes it by itself. The index keeps each value's sketch; a search ranks the sketches of the
-- cells nearest the query, then its nearest arg.ivf_candidates by SIM, read from the table, so
-- rows come back in exact SIM order. With every cell probed and every row a candidate it
-- answers as ordering every row by <~> does.

CREATE EXTENSION arg;

CREATE TABLE objects (
  id     int PRIMARY KEY,
  class  text NOT NULL,
  period text NOT NULL,
  descr  arg
);
INSERT INTO objects (id, class, period, descr)
SELECT i, c.class, CASE WHEN i % 5 = 0 THEN 'Roman' ELSE 'Modern' END,
       arg_build(arg_generate_model(c.class, i / 9, 16))
FROM generate_series(0, 44) AS i,
     LATERAL (SELECT (ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table',
                            'chair', 'octopus'])[i % 9 + 1] AS class) AS c;
INSERT INTO objects VALUES (100, 'no model', 'Modern', NULL);
ANALYZE objects;
SELECT descr AS q FROM objects WHERE id = 0 \gset

CREATE INDEX objects_descr ON objects USING arg_ivf (descr) WITH (lists = 5);
SELECT amvalidate(c.oid) AS opclass_valid, c.opcdefault AS is_default
FROM pg_opclass c JOIN pg_am am ON am.oid = c.opcmethod
WHERE c.opcname = 'arg_ops' AND am.amname = 'arg_ivf';

-- The plan of a query, without its literals (an ARG literal is thousands of characters).
CREATE FUNCTION plan_of(query text) RETURNS SETOF text LANGUAGE plpgsql AS $$
DECLARE line text;
BEGIN
  FOR line IN EXECUTE 'EXPLAIN (COSTS OFF) ' || query LOOP
    RETURN NEXT regexp_replace(line, '''arg1:[^'']*''', '''...''', 'g');
  END LOOP;
END $$;

-- The plain query takes the index for a parameter, a literal and a scalar subquery.
SET enable_seqscan = off;
SET plan_cache_mode = force_generic_plan;
PREPARE nearest(arg, int) AS SELECT id FROM objects ORDER BY descr <~> $1 LIMIT $2;
EXPLAIN (COSTS OFF) EXECUTE nearest(NULL, 5);
SELECT plan_of(format('SELECT id FROM objects ORDER BY descr <~> %L::arg LIMIT 5', :'q'));
EXPLAIN (COSTS OFF)
SELECT id FROM objects ORDER BY descr <~> (SELECT descr FROM objects WHERE id = 7) LIMIT 5;
RESET enable_seqscan;
-- Taken on its own costs, too, over a sort of every row (one SIM a row).
EXPLAIN (COSTS OFF)
SELECT id FROM objects ORDER BY descr <~> (SELECT descr FROM objects WHERE id = 7) LIMIT 5;
SET enable_seqscan = off;

-- Every cell, every row a candidate: exactly brute force's order and SIMs, for every query.
SET arg.ivf_probes = 5;
SET arg.ivf_candidates = 100;
SELECT count(*) AS queries,
       bool_and(i.ids = e.ids) AS same_order_as_brute_force,
       bool_and(i.sims = e.sims) AS same_sims,
       bool_and(cardinality(i.ids) = 45) AS every_indexed_row
FROM objects q,
     LATERAL (SELECT array_agg(id) AS ids, array_agg(sim) AS sims
              FROM (SELECT id, descr <~> q.descr AS sim FROM objects
                    ORDER BY descr <~> q.descr LIMIT 50) s) i,
     LATERAL (SELECT array_agg(id ORDER BY descr <~> q.descr, id) AS ids,
                     array_agg(descr <~> q.descr ORDER BY descr <~> q.descr, id) AS sims
              FROM objects WHERE descr IS NOT NULL) e
WHERE q.descr IS NOT NULL;

-- Fewer candidates than rows: still in exact SIM order among the rows returned, each query
-- first (its own SIM is 0), and most of brute force's five nearest.
SET arg.ivf_probes = 2;
SET arg.ivf_candidates = 10;
SET arg.iterative_scan = off;
SELECT bool_and(i.ids[1] = q.id) AS finds_itself_first,
       bool_and(i.sims = (SELECT array_agg(x ORDER BY x) FROM unnest(i.sims) x)) AS in_sim_order,
       avg(cardinality(ARRAY(SELECT unnest(i.ids[1:5]) INTERSECT SELECT unnest(e.ids))) / 5.0)
         >= 0.8 AS recall_of_five_at_least_80_percent,
       max(cardinality(i.ids)) <= 10 AS one_batch_without_iteration
FROM objects q,
     LATERAL (SELECT array_agg(id) AS ids, array_agg(sim) AS sims
              FROM (SELECT id, descr <~> q.descr AS sim FROM objects
                    ORDER BY descr <~> q.descr LIMIT 45) s) i,
     LATERAL (SELECT array_agg(id) AS ids
              FROM (SELECT id FROM objects WHERE descr IS NOT NULL
                    ORDER BY descr <~> q.descr, id LIMIT 5) s) e
WHERE q.descr IS NOT NULL;

-- A filter: the scan goes on past its first candidates until the LIMIT is met (nine Roman
-- objects, five asked for), in SIM order.
SET arg.iterative_scan = strict_order;
SET arg.ivf_probes = 1;
SET arg.ivf_candidates = 5;
SELECT plan_of(format('SELECT id FROM objects WHERE period = ''Roman''
                       ORDER BY descr <~> %L::arg LIMIT 5', :'q'));
SELECT count(*) AS roman_rows,
       bool_and(period = 'Roman') AS all_roman,
       array_agg(sim) = (SELECT array_agg(x ORDER BY x) FROM unnest(array_agg(sim)) x)
         AS in_sim_order,
       cardinality(ARRAY(SELECT unnest(array_agg(id)) INTERSECT
                         SELECT id FROM (SELECT id FROM objects WHERE period = 'Roman'
                                         ORDER BY descr <~> :'q'::arg, id LIMIT 5) b))
         AS found_of_brute_forces_five
FROM (SELECT id, period, descr <~> :'q'::arg AS sim FROM objects
      WHERE period = 'Roman' ORDER BY descr <~> :'q'::arg LIMIT 5) s;
-- Without iteration the first candidates are all there is.
SET arg.iterative_scan = off;
SELECT count(*) <= 5 AS at_most_the_first_candidates
FROM (SELECT id FROM objects WHERE period = 'Roman' ORDER BY descr <~> :'q'::arg LIMIT 5) s;
-- Relaxed order returns every Roman object at last, as brute force does.
SET arg.iterative_scan = relaxed_order;
SELECT array_agg(id ORDER BY id) = (SELECT array_agg(id ORDER BY id) FROM objects
                                    WHERE period = 'Roman') AS every_roman_object
FROM (SELECT id FROM objects WHERE period = 'Roman' ORDER BY descr <~> :'q'::arg LIMIT 20) s;
-- arg.max_scan_tuples bounds what one search ranks by SIM (the first batch is always ranked).
SET arg.max_scan_tuples = 5;
SELECT count(*) <= 10 AS bounded
FROM (SELECT id FROM objects WHERE period = 'Roman' ORDER BY descr <~> :'q'::arg LIMIT 20) s;
RESET arg.max_scan_tuples;
RESET arg.iterative_scan;

-- A NULL query has no nearest: every indexed row, in no order. A literal NULL folds the ORDER BY
-- away (<~> is strict), so a query passes it as a parameter or a subquery.
SET arg.ivf_probes = 1;
SELECT count(*) AS rows FROM (SELECT id FROM objects ORDER BY descr <~> (SELECT NULL::arg) LIMIT 100) s;
EXECUTE nearest(NULL, 100);

-- Rows inserted after the build join their nearest cell and are found; an updated row moves;
-- deleted rows leave with VACUUM, and later inserts reuse their space.
SET arg.ivf_probes = 5;
SET arg.ivf_candidates = 100;
INSERT INTO objects (id, class, period, descr)
SELECT 45 + i, 'cup', 'Roman', arg_build(arg_generate_model('cup', 10 + i, 16))
FROM generate_series(0, 5) AS i;
UPDATE objects SET descr = arg_build(arg_generate_model('torus', 20, 16)) WHERE id = 1;
SELECT descr AS q1 FROM objects WHERE id = 1 \gset
SELECT (SELECT id FROM objects ORDER BY descr <~> :'q1'::arg LIMIT 1) AS updated_row_first,
       (SELECT count(*) FROM (SELECT id FROM objects ORDER BY descr <~> :'q'::arg LIMIT 100) s)
         AS rows;
DELETE FROM objects WHERE id >= 45;
VACUUM objects;
SELECT pg_relation_size('objects_descr') AS size_after_vacuum \gset
INSERT INTO objects (id, class, period, descr)
SELECT 45 + i, 'cup', 'Roman', arg_build(arg_generate_model('cup', 10 + i, 16))
FROM generate_series(0, 5) AS i;
SELECT pg_relation_size('objects_descr') = :size_after_vacuum AS inserts_reuse_vacuumed_space;
SELECT array_agg(id) = (SELECT array_agg(id ORDER BY descr <~> :'q'::arg, id)
                        FROM objects WHERE descr IS NOT NULL) AS exact_after_churn
FROM (SELECT id FROM objects ORDER BY descr <~> :'q'::arg LIMIT 100) s;
-- The index holds every live row once, under its value's sketch, before and after a rebuild.
SELECT * FROM arg_index_check('objects_descr');
REINDEX INDEX objects_descr;
REINDEX INDEX CONCURRENTLY objects_descr;
SELECT * FROM arg_index_check('objects_descr');
SELECT count(*) AS rows_after_reindex
FROM (SELECT id FROM objects ORDER BY descr <~> :'q'::arg LIMIT 100) s;

-- A generated column and a column kept by the trigger: the same index, the same answers.
CREATE TABLE models (id int PRIMARY KEY, mesh bytea,
                     descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);
CREATE TABLE kept (id int PRIMARY KEY, mesh bytea, descr arg);
CREATE TRIGGER kept_descr BEFORE INSERT OR UPDATE ON kept
  FOR EACH ROW EXECUTE FUNCTION arg_index_trigger('mesh', 'descr');
INSERT INTO models (id, mesh)
SELECT i, arg_generate_model((ARRAY['vase', 'human', 'table'])[i % 3 + 1], i, 16)
FROM generate_series(0, 8) AS i;
INSERT INTO kept SELECT id, mesh FROM models;
CREATE INDEX ON models USING arg_ivf (descr) WITH (lists = 2);
CREATE INDEX ON kept USING arg_ivf (descr) WITH (lists = 2);
SET arg.ivf_probes = 2;
SELECT plan_of(format('SELECT id FROM models ORDER BY descr <~> %L::arg LIMIT 3', :'q'));
SELECT plan_of(format('SELECT id FROM kept ORDER BY descr <~> %L::arg LIMIT 3', :'q'));
SELECT (SELECT array_agg(id) FROM (SELECT id FROM models ORDER BY descr <~> :'q'::arg LIMIT 9) s)
     = (SELECT array_agg(id) FROM (SELECT id FROM kept ORDER BY descr <~> :'q'::arg LIMIT 9) s)
       AS generated_and_kept_agree,
       (SELECT array_agg(id) FROM (SELECT id FROM kept ORDER BY descr <~> :'q'::arg LIMIT 9) s)
     = (SELECT array_agg(id ORDER BY descr <~> :'q'::arg, id) FROM kept) AS kept_as_brute_force;
UPDATE kept SET mesh = arg_generate_model('torus', 3, 16) WHERE id = 4;
SELECT id AS nearest_torus FROM kept
ORDER BY descr <~> arg_build(arg_generate_model('torus', 3, 16)) LIMIT 1;
DROP TABLE models, kept;

-- An empty table's index has one cell, which every row joins; an unlogged table's too.
CREATE UNLOGGED TABLE later (id int, descr arg);
CREATE INDEX later_descr ON later USING arg_ivf (descr);
SELECT count(*) AS empty FROM (SELECT id FROM later ORDER BY descr <~> :'q'::arg LIMIT 5) s;
INSERT INTO later SELECT id, descr FROM objects;
SELECT array_agg(id) = (SELECT array_agg(id ORDER BY descr <~> :'q'::arg, id)
                        FROM later WHERE descr IS NOT NULL) AS one_cell_exact
FROM (SELECT id FROM later ORDER BY descr <~> :'q'::arg LIMIT 100) s;

-- Errors: an index of an expression could not read its values back from the table; the check
-- takes only an arg_ivf index.
CREATE INDEX ON objects USING arg_ivf (arg_build(arg_generate_model(class, id, 16)));
CREATE INDEX ON objects USING arg_ivf (descr, id);
SELECT * FROM arg_index_check('objects_pkey');
SELECT * FROM arg_index_check('objects');
SET arg.ivf_candidates = -1;
SET arg.iterative_scan = sideways;
SET arg.max_scan_tuples = 0;

DEALLOCATE nearest;
RESET ALL;
DROP TABLE objects, later;
DROP FUNCTION plan_of(text);
DROP EXTENSION arg;
