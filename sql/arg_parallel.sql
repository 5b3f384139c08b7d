-- arg_parallel: every function is PARALLEL SAFE, so ranking a large table can use parallel
-- workers. Parallel costs are set low here so that the planner picks a parallel plan for a
-- table of 200 small models; on a real catalogue the defaults do.

CREATE EXTENSION arg;

CREATE TABLE catalogue (
  id    int PRIMARY KEY,
  class text NOT NULL,
  mesh  bytea NOT NULL,
  descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED
) WITH (parallel_workers = 2);
INSERT INTO catalogue (id, class, mesh)
SELECT i, c.class, arg_generate_model(c.class, i / 9, 16)
FROM generate_series(0, 199) AS i,
     LATERAL (SELECT (ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table',
                            'chair', 'octopus'])[i % 9 + 1] AS class) AS c;
ANALYZE catalogue;

SET parallel_setup_cost = 0;
SET parallel_tuple_cost = 0;
SET min_parallel_table_scan_size = 0;
SET max_parallel_workers_per_gather = 2;

-- The ten models most like model 0: workers scan and score parts of the table, each sorts
-- its rows, and Gather Merge keeps the best ten.
EXPLAIN (COSTS OFF)
SELECT id, class FROM catalogue
ORDER BY descr <~> (SELECT descr FROM catalogue WHERE id = 0) LIMIT 10;

-- The parallel plan gives the same answer as a serial one.
CREATE TABLE parallel_answer AS
SELECT id, descr <~> (SELECT descr FROM catalogue WHERE id = 0) AS sim FROM catalogue
ORDER BY descr <~> (SELECT descr FROM catalogue WHERE id = 0), id LIMIT 10;
SET max_parallel_workers_per_gather = 0;
SELECT count(*) AS same_rows
FROM (SELECT id, descr <~> (SELECT descr FROM catalogue WHERE id = 0) AS sim FROM catalogue
      ORDER BY descr <~> (SELECT descr FROM catalogue WHERE id = 0), id LIMIT 10) serial
JOIN parallel_answer USING (id, sim);

-- Filtering on metadata (here the class) keeps the plan parallel.
SET max_parallel_workers_per_gather = 2;
EXPLAIN (COSTS OFF)
SELECT id FROM catalogue WHERE class IN ('cup', 'vase')
ORDER BY descr <~> (SELECT descr FROM catalogue WHERE id = 1) LIMIT 5;

RESET ALL;
DROP TABLE catalogue, parallel_answer;
DROP EXTENSION arg;
