-- arg_type: the arg and arg_weights types. Every way a value leaves the server and comes back
-- (text, binary, COPY in both formats) gives the same bytes, and equal values compare equal.

CREATE EXTENSION arg;

-- Two generated models of each of three classes, as meshes (OFF bytes) and their ARGs.
CREATE TABLE models AS
SELECT c.class || '_' || v AS name, arg_build(arg_generate_model(c.class, v, 24)) AS descr
FROM unnest(ARRAY['cup', 'human', 'torus']) AS c(class), generate_series(0, 1) AS v;

-- Stored out of line and uncompressed (like pgvector): ranking reads every value.
SELECT typname, typlen, typstorage, typalign FROM pg_type WHERE typname IN ('arg', 'arg_weights')
ORDER BY typname;

-- Text form: a version tag, then base64 of the binary form; reading it back gives the same
-- bytes. arg_send gives the binary form itself.
SELECT name, left(descr::text, 5) AS tag,
       length(descr::text) - 5 = 4 * ceil(octet_length(arg_send(descr)) / 3.0) AS base64_length,
       descr::text::arg = descr AS text_round_trip,
       arg_send(descr::text::arg) = arg_send(descr) AS same_bytes
FROM models ORDER BY name;

-- The binary form is versioned: it starts with a magic number and the format version.
SELECT DISTINCT substr(arg_send(descr), 1, 6) AS magic_and_version FROM models;

-- COPY in text and binary format (here through psql's \copy, to files in the test's output
-- directory) reads back byte-identical values; binary COPY goes through arg_send and arg_recv.
\getenv abs_builddir PG_ABS_BUILDDIR
\cd :abs_builddir
\copy models TO 'arg_type_models.txt'
\copy models TO 'arg_type_models.bin' WITH (FORMAT binary)
CREATE TABLE from_text (LIKE models);
CREATE TABLE from_binary (LIKE models);
\copy from_text FROM 'arg_type_models.txt'
\copy from_binary FROM 'arg_type_models.bin' WITH (FORMAT binary)
SELECT m.name,
       arg_send(t.descr) = arg_send(m.descr) AS text_copy_identical,
       arg_send(b.descr) = arg_send(m.descr) AS binary_copy_identical
FROM models m JOIN from_text t USING (name) JOIN from_binary b USING (name) ORDER BY m.name;

-- Equality is byte equality, so = , DISTINCT, GROUP BY, UNION and joins work on arg values;
-- hashing reads only the digest stored in each value.
INSERT INTO models SELECT name || '_copy', descr FROM models WHERE name LIKE 'cup%';
SELECT count(*) AS rows, count(DISTINCT descr) AS distinct_values FROM models;
SELECT count(*) AS groups FROM (SELECT descr FROM models GROUP BY descr) g;
SELECT string_agg(a.name || '=' || b.name, ', ' ORDER BY a.name) AS equal_pairs
FROM models a JOIN models b ON a.descr = b.descr AND a.name < b.name;
SELECT count(*) AS union_rows FROM (SELECT descr FROM models UNION SELECT descr FROM from_text) u;
-- The order operators give a canonical total order (by digest), not an order of shape.
SELECT bool_and((a.descr < b.descr) = (arg_cmp(a.descr, b.descr) < 0)
                AND (a.descr = b.descr) = (arg_cmp(a.descr, b.descr) = 0)
                AND (a.descr < b.descr) <> (a.descr >= b.descr)) AS consistent_order
FROM models a, models b;
CREATE INDEX models_descr_hash ON models USING hash (descr);
SET enable_seqscan = off;
SELECT name FROM models WHERE descr = (SELECT descr FROM from_text WHERE name = 'torus_1');
RESET enable_seqscan;

-- arg_weights: a small fixed-size value read from a preset name, key=value pairs, or both;
-- its output is the canonical list of every weight, which reads back to the same value.
SELECT typname, typlen FROM pg_type WHERE typname = 'arg_weights';
SELECT preset, preset::arg_weights AS weights
FROM unnest(ARRAY['arg', 'mrg', 'shape', 'colour']) AS preset;
SELECT 'shape lambda_1=0.1, norm=l2'::arg_weights AS preset_then_pairs;
SELECT 'alpha_l=.3 beta_l=.15 gamma_l=.15 delta_l=.2 eps_l=.2 alpha_s=.65 beta_s=.35 '
       'lambda_1=.3 lambda_2=1 lambda_3=3 lambda_4=.1'::arg_weights AS explicit;
SELECT w::text::arg_weights::text = w::text AS text_round_trip
FROM (SELECT 'mrg lambda_2=0.123456789'::arg_weights AS w) s;
CREATE TABLE weight_sets (name text, w arg_weights);
INSERT INTO weight_sets VALUES ('default', 'arg'), ('topology', 'mrg'), ('custom', 'shape tung=off'),
  ('proxies', 'arg graph_on_proxy=0.35 groups=on norm=l2'),
  ('coarse', 'arg level_ratio=0.65 eps_l=0'), ('coarsest', 'mrg level_ratio=0');
\copy weight_sets TO 'arg_type_weights.bin' WITH (FORMAT binary)
CREATE TABLE weight_sets_back (LIKE weight_sets);
\copy weight_sets_back FROM 'arg_type_weights.bin' WITH (FORMAT binary)
SELECT a.name, a.w::text = b.w::text AS binary_round_trip
FROM weight_sets a JOIN weight_sets_back b USING (name) ORDER BY a.name;
-- level_ratio is kept in the value's spare bits and sent as a 49th byte when it is not 1.
SELECT name, length(arg_weights_send(w)) AS binary_bytes,
       substring(w::text FROM 'level_ratio=[0-9.]+') AS level_ratio, substring(w::text FROM 'eps_l=[0-9.]+') AS eps_l
FROM weight_sets ORDER BY name;
\! rm -f arg_type_models.txt arg_type_models.bin arg_type_weights.bin

-- Input is validated as strictly in text as in binary.
SELECT 'arg1:'::arg;
SELECT 'arg2:AAAA'::arg;
SELECT 'arg1:not base64!'::arg;
-- One base64 character changed in the middle: the digest no longer matches.
SELECT ('arg1:' || overlay(t PLACING CASE WHEN substr(t, 2001, 1) = 'B' THEN 'C' ELSE 'B' END
                           FROM 2001 FOR 1))::arg
FROM (SELECT substr(descr::text, 6) AS t FROM models WHERE name = 'cup_0') s;
SELECT 'lambda_1=-1'::arg_weights;
SELECT 'lambda_1'::arg_weights;
SELECT 'arg graph_on_proxy=1.5'::arg_weights;
SELECT 'arg level_ratio=1.05'::arg_weights;
SELECT 'alpha_s=0 beta_s=0 lambda_1=0 lambda_2=0 lambda_3=0 lambda_4=0'::arg_weights;

DROP TABLE models, from_text, from_binary, weight_sets, weight_sets_back;
DROP EXTENSION arg;
