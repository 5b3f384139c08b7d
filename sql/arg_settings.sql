-- arg_settings: the extension's settings, and what happens when input is refused or a query is
-- cancelled. Settings only cap resources or switch a cache; none changes a result.

CREATE EXTENSION arg;

SELECT name, setting, unit, context, vartype FROM pg_settings WHERE name LIKE 'arg.%' ORDER BY name;

-- The prefix is reserved: a misspelt setting is an error, not a silent placeholder.
SET arg.max_input_sise = '1MB';

-- The caps refuse input that is too large, before it is read.
CREATE TABLE big AS SELECT arg_generate_model('human', 0, 128) AS mesh;
SET arg.max_input_size = '64kB';
SELECT arg_build(mesh) FROM big;
RESET arg.max_input_size;
SET arg.max_triangles = 1000;
SELECT arg_build(mesh) FROM big;
RESET arg.max_triangles;
SET arg.max_vertices = 1000;
SELECT arg_build(mesh) FROM big;
RESET arg.max_vertices;

-- A long build stops when the statement times out (or is cancelled); the session goes on.
SET statement_timeout = '20ms';
SELECT arg_build(mesh) FROM big;
RESET statement_timeout;
SELECT octet_length(mesh) > 1000000 AS big_mesh_still_there FROM big;

-- The query cache (arg.query_cache) only saves work: scores are the same without it.
CREATE TABLE few AS
SELECT c AS class, arg_build(arg_generate_model(c, 0, 16)) AS descr
FROM unnest(ARRAY['cup', 'vase', 'chair']) AS c;
CREATE TABLE with_cache AS
SELECT a.class AS a, b.class AS b, a.descr <~> b.descr AS sim FROM few a, few b;
SET arg.query_cache = off;
SELECT bool_and(w.sim = a.descr <~> b.descr) AS same_scores
FROM with_cache w JOIN few a ON a.class = w.a JOIN few b ON b.class = w.b;
RESET arg.query_cache;
-- With the cache, a value that repeats is also prepared for matching once (for each weights
-- it meets): the same scores to the bit, for other weights and with colour too.
CREATE TABLE weighed AS
SELECT a.class AS a, b.class AS b, w, arg_sim(a.descr, b.descr, w::arg_weights) AS sim
FROM few a, few b, unnest(ARRAY['mrg', 'colour', 'arg']) AS w;
SET arg.query_cache = off;
SELECT bool_and(w.sim = arg_sim(a.descr, b.descr, w.w::arg_weights)) AS same_weighed_scores,
       count(*) AS pairs
FROM weighed w JOIN few a ON a.class = w.a JOIN few b ON b.class = w.b;
RESET arg.query_cache;

-- Each class of failure has its SQLSTATE: bad input 22P02 (text of a type) or 22023 (an
-- argument), binary input of a type 22P03, over a cap 54000, cancelled 57014.
\set VERBOSITY sqlstate
SELECT arg_build(convert_to('OFF
3 1 0
0 0 0
', 'UTF8'));
SELECT arg_build('\x00ff'::bytea);
SELECT arg_build(mesh, 'levels=9') FROM big;
SELECT 'arg1:AAAA'::arg;
SELECT 'no_such_preset'::arg_weights;
SELECT arg_generate_model('teapot', 0);
SELECT arg_svg(descr, 7) FROM few WHERE class = 'cup';
SET arg.max_input_size = '64kB';
SELECT arg_build(mesh) FROM big;
RESET arg.max_input_size;
SET statement_timeout = '20ms';
SELECT arg_build(mesh) FROM big;
RESET statement_timeout;
\set VERBOSITY default
SELECT 'still answering' AS session;

DROP TABLE big, few, with_cache, weighed;
DROP EXTENSION arg;
