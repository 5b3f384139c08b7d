-- arg_settings: the extension's settings, and what happens when input is refused or a query is
-- cancelled. Settings cap resources, switch a cache or set how much of an arg_ivf index a search
-- reads; none changes a function's result.

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
-- A build whose memory estimate is over arg.max_build_memory is refused from the mesh's counts.
SET arg.max_build_memory = '16MB';
SELECT arg_build(mesh) FROM big;
RESET arg.max_build_memory;

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

-- A ranking reads each row straight into the matcher's keys (format 3 without colour) once its
-- query repeats: the same scores to the bit as reading every row whole (the cache off), for
-- the weights that read node records (mrg groups nodes) and those that do not.
-- The generated meshes colour their faces: the colour is taken off all but variant 3's, whose
-- rows take the decoded path.
CREATE TABLE ranked AS
SELECT row_number() OVER (ORDER BY c, v)::int AS id, c AS class,
       arg_build(CASE WHEN v = 3 THEN m ELSE convert_to(regexp_replace(convert_from(m, 'UTF8'),
                 '^(3 \d+ \d+ \d+) \d+ \d+ \d+$', '\1', 'gn'), 'UTF8') END) AS descr
FROM unnest(ARRAY['cup', 'vase', 'chair', 'human', 'fourleg', 'octopus']) AS c,
     generate_series(0, 3) AS v, arg_generate_model(c, v, 16) AS m;
SELECT count(*) AS rows, count(*) FILTER (WHERE (arg_info(descr)->>'has_colour')::bool) AS coloured
FROM ranked;
-- Each query and weights rank every row: the row varies call after call, the query repeats.
CREATE FUNCTION pg_temp.scores(qid int, w text)
RETURNS TABLE (id int, sim bytea, dist bytea) LANGUAGE sql AS $$
  SELECT r.id, float8send(arg_sim(r.descr, (SELECT descr FROM ranked WHERE id = qid),
                                  w::arg_weights)),
         float8send(r.descr <~> (SELECT descr FROM ranked WHERE id = qid))
  FROM ranked r $$;
CREATE TABLE ranked_with_cache AS
SELECT qid, w, s.* FROM unnest(ARRAY[1, 14]) AS qid,
       unnest(ARRAY['arg', 'shape', 'graph', 'mrg']) AS w, LATERAL pg_temp.scores(qid, w) AS s;
SET arg.query_cache = off;
SELECT count(*) AS scores, bool_and(c.sim = s.sim AND c.dist = s.dist) AS same_bits
FROM ranked_with_cache c, LATERAL pg_temp.scores(c.qid, c.w) AS s WHERE s.id = c.id;
RESET arg.query_cache;
-- A row built with other options stops the ranking with the same error either way.
INSERT INTO ranked VALUES (25, 'cup', arg_build(arg_generate_model('cup', 9, 16), 'levels=4'));
\set VERBOSITY terse
SELECT id FROM ranked ORDER BY descr <~> (SELECT descr FROM ranked WHERE id = 1) LIMIT 3;
SET arg.query_cache = off;
SELECT id FROM ranked ORDER BY descr <~> (SELECT descr FROM ranked WHERE id = 1) LIMIT 3;
RESET arg.query_cache;
\set VERBOSITY default
DROP TABLE ranked, ranked_with_cache;

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

-- The extension is trusted: a role that may create in the database (a database owner, say)
-- installs it without being a superuser, and owns it; the caps stay a superuser's to change.
CREATE ROLE arg_owner;
DO $$ BEGIN EXECUTE format('GRANT CREATE ON DATABASE %I TO arg_owner', current_database()); END $$;
SET ROLE arg_owner;
CREATE EXTENSION arg;
SELECT r.rolname AS owner, r.rolsuper AS superuser
FROM pg_extension e JOIN pg_roles r ON r.oid = e.extowner WHERE e.extname = 'arg';
SELECT arg_version() LIKE 'arg %' AS loads;
SET arg.max_input_size = '1GB';
DROP EXTENSION arg;
RESET ROLE;
DO $$ BEGIN EXECUTE format('REVOKE CREATE ON DATABASE %I FROM arg_owner', current_database()); END $$;
DROP ROLE arg_owner;
