-- No input crashes the server. Every function and operator of the extension (found in the
-- catalogue, so a new function is covered without editing this file) is called with NULL, empty
-- values, deterministic random bytes, truncated valid inputs (OFF, PLY, STL, OBJ and GLB meshes
-- and BMP and TGA textures made here in SQL, the binary and text forms of an ARG), every weights
-- preset, extreme and malformed weights, unusual valid ARGs and, as a superuser, forged ARG
-- values that never went through input validation. One argument is hostile at a time, the
-- others are valid. Each call either answers or fails with a proper SQLSTATE: a data exception
-- (class 22), 54000 over a cap, 08P01 for binary input shorter than its type (PostgreSQL's own
-- pq_getmsg* check), XX001 only for a forged value; never XX000. Afterwards the same backend
-- still answers. tests/run_all.sh then checks the server log for "terminated by signal".
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SET LOCAL client_min_messages = warning;

CREATE TEMP TABLE session AS SELECT pg_backend_pid() AS pid;

-- Helpers -----------------------------------------------------------------------------------

-- n deterministic "random" bytes: an md5 chain of seed.
CREATE FUNCTION pg_temp.noise(seed text, n int) RETURNS bytea LANGUAGE sql IMMUTABLE AS $$
  SELECT coalesce(substr(string_agg(decode(md5(seed || '/' || i), 'hex'), ''::bytea ORDER BY i), 1, n),
                  ''::bytea)
  FROM generate_series(0, greatest(n - 1, 0) / 16) i $$;

-- Little-endian encodings (the send functions give network byte order).
CREATE FUNCTION pg_temp.le(b bytea) RETURNS bytea LANGUAGE sql IMMUTABLE AS $$
  SELECT string_agg(substr(b, i, 1), ''::bytea ORDER BY i DESC) FROM generate_series(1, length(b)) i $$;
CREATE FUNCTION pg_temp.f32(x float8) RETURNS bytea LANGUAGE sql IMMUTABLE AS
  $$ SELECT pg_temp.le(float4send(x::float4)) $$;
CREATE FUNCTION pg_temp.u32(n bigint) RETURNS bytea LANGUAGE sql IMMUTABLE AS
  $$ SELECT pg_temp.le(int4send(n::int4)) $$;
CREATE FUNCTION pg_temp.u16(n int) RETURNS bytea LANGUAGE sql IMMUTABLE AS
  $$ SELECT pg_temp.le(int2send(n::int2)) $$;
CREATE FUNCTION pg_temp.u8(n int) RETURNS bytea LANGUAGE sql IMMUTABLE AS
  $$ SELECT set_byte('\x00'::bytea, 0, n) $$;

-- Runs one query; returns its SQLSTATE ('00000' on success) and, on success, its result.
-- A cancel (statement_timeout) is not caught: it fails the whole file.
CREATE FUNCTION pg_temp.attempt(query text, OUT state text, OUT result text, OUT message text)
LANGUAGE plpgsql AS $$
BEGIN
  EXECUTE query INTO result;
  state := '00000';
EXCEPTION WHEN others THEN
  state := SQLSTATE;
  message := SQLERRM;
END $$;

-- One test over many calls: ok when each call succeeds with a sane result (not NaN unless
-- nan_ok) or fails with a SQLSTATE matching `allowed`, each within 10 s; the calls that do not
-- are listed as diagnostics.
CREATE FUNCTION pg_temp.check_calls(description text, queries text[], allowed text, nan_ok bool) RETURNS text
LANGUAGE plpgsql AS $$
DECLARE
  q text;
  o record;
  bad text[] := '{}';
  states text[] := '{}';
  started timestamptz;
  slow text[] := '{}';
BEGIN
  FOREACH q IN ARRAY queries LOOP
    started := clock_timestamp();
    o := pg_temp.attempt(q);
    IF clock_timestamp() - started > interval '10 s' THEN
      slow := slow || format('%s s: %s', round(extract(epoch FROM clock_timestamp() - started)::numeric, 1), q);
    END IF;
    IF NOT o.state = ANY (states) THEN states := states || o.state; END IF;
    IF o.state !~ allowed THEN
      bad := bad || format('%s (%s) from %s', o.state, o.message, left(q, 300));
    ELSIF o.state = '00000' AND o.result ~* '^-?nan$' AND NOT nan_ok THEN
      bad := bad || format('NaN result %s from %s', left(o.result, 100), left(q, 300));
    END IF;
  END LOOP;
  RETURN ok(cardinality(bad) = 0 AND cardinality(slow) = 0,
            format('%s: %s calls, SQLSTATEs %s', description, cardinality(queries),
                   array_to_string(ARRAY(SELECT unnest(states) ORDER BY 1), ' ')))
      || CASE WHEN cardinality(bad) + cardinality(slow) > 0
              THEN E'\n' || diag(array_to_string((bad || slow)[1:10], E'\n')) ELSE '' END;
END $$;

-- Valid inputs, made here ---------------------------------------------------------------------

-- A small closed, coloured mesh (about 700 triangles) as the generator writes it (OFF), parsed.
CREATE TEMP TABLE model AS SELECT arg_generate_model('cup', 1, 8) AS off;
CREATE TEMP TABLE off_lines AS
SELECT n::int - 1 AS line, l FROM model, string_to_table(convert_from(off, 'UTF8'), E'\n') WITH ORDINALITY AS t(l, n);
CREATE TEMP TABLE counts AS
SELECT split_part(l, ' ', 1)::int AS nv, split_part(l, ' ', 2)::int AS nf FROM off_lines WHERE line = 1;
CREATE TEMP TABLE verts AS
SELECT line - 2 AS i, split_part(l, ' ', 1)::float8 AS x, split_part(l, ' ', 2)::float8 AS y,
       split_part(l, ' ', 3)::float8 AS z
FROM off_lines, counts WHERE line BETWEEN 2 AND nv + 1;
CREATE TEMP TABLE faces AS
SELECT line - nv - 2 AS i, split_part(l, ' ', 2)::int AS a, split_part(l, ' ', 3)::int AS b,
       split_part(l, ' ', 4)::int AS c, coalesce(nullif(split_part(l, ' ', 5), ''), '200')::int AS r,
       coalesce(nullif(split_part(l, ' ', 6), ''), '100')::int AS g,
       coalesce(nullif(split_part(l, ' ', 7), ''), '50')::int AS bl
FROM off_lines, counts WHERE line BETWEEN nv + 2 AND nv + nf + 1;
CREATE TEMP TABLE corners AS
SELECT f.i, k, v.x, v.y, v.z
FROM faces f, LATERAL (VALUES (0, f.a), (1, f.b), (2, f.c)) AS t(k, vi) JOIN verts v ON v.i = t.vi;

-- The same mesh in every format arg_build reads, and two small textures.
CREATE TEMP TABLE valid (name text PRIMARY KEY, bytes bytea);
INSERT INTO valid SELECT 'OFF', off FROM model;
INSERT INTO valid SELECT 'PLY (ASCII)', convert_to(
  format(E'ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\n'
         'element face %s\nproperty list uchar int vertex_indices\nproperty uchar red\n'
         'property uchar green\nproperty uchar blue\nend_header\n', nv, nf)
  || (SELECT string_agg(format('%s %s %s', x, y, z), E'\n' ORDER BY i) FROM verts) || E'\n'
  || (SELECT string_agg(format('3 %s %s %s %s %s %s', a, b, c, r, g, bl), E'\n' ORDER BY i) FROM faces) || E'\n',
  'UTF8') FROM counts;
INSERT INTO valid SELECT 'PLY (binary)', convert_to(
  format(E'ply\nformat binary_little_endian 1.0\nelement vertex %s\nproperty float x\nproperty float y\n'
         'property float z\nelement face %s\nproperty list uchar int vertex_indices\nproperty uchar red\n'
         'property uchar green\nproperty uchar blue\nend_header\n', nv, nf), 'UTF8')
  || (SELECT string_agg(pg_temp.f32(x) || pg_temp.f32(y) || pg_temp.f32(z), ''::bytea ORDER BY i) FROM verts)
  || (SELECT string_agg(pg_temp.u8(3) || pg_temp.u32(a) || pg_temp.u32(b) || pg_temp.u32(c)
                        || pg_temp.u8(r) || pg_temp.u8(g) || pg_temp.u8(bl), ''::bytea ORDER BY i) FROM faces)
FROM counts;
INSERT INTO valid SELECT 'STL (ASCII)', convert_to(
  E'solid cup\n' || string_agg(format(E'facet normal 0 0 0\n outer loop\n%s\n endloop\nendfacet', vs), E'\n' ORDER BY i)
  || E'\nendsolid cup\n', 'UTF8')
FROM (SELECT i, string_agg(format('  vertex %s %s %s', x, y, z), E'\n' ORDER BY k) AS vs FROM corners GROUP BY i) t;
INSERT INTO valid SELECT 'STL (binary)',
  convert_to(rpad('binary STL written by 02_no_crash.sql', 80), 'UTF8') || pg_temp.u32(count(*))
  || string_agg(pg_temp.f32(0) || pg_temp.f32(0) || pg_temp.f32(0) || vs || pg_temp.u16(0), ''::bytea ORDER BY i)
FROM (SELECT i, string_agg(pg_temp.f32(x) || pg_temp.f32(y) || pg_temp.f32(z), ''::bytea ORDER BY k) AS vs
      FROM corners GROUP BY i) t;
INSERT INTO valid SELECT 'OBJ', convert_to(
  (SELECT string_agg(format('v %s %s %s', x, y, z), E'\n' ORDER BY i) FROM verts) || E'\n'
  || (SELECT string_agg(format('f %s %s %s', a + 1, b + 1, c + 1), E'\n' ORDER BY i) FROM faces) || E'\n', 'UTF8');
-- With texture coordinates, for arg_build(mesh, texture).
INSERT INTO valid SELECT 'OBJ (textured)', convert_to(
  (SELECT string_agg(format('v %s %s %s', x, y, z), E'\n' ORDER BY i) FROM verts) || E'\n'
  || (SELECT string_agg(format('vt %s %s', (x + 1) / 2, (z + 1) / 2), E'\n' ORDER BY i) FROM verts) || E'\n'
  || (SELECT string_agg(format('f %s/%s %s/%s %s/%s', a + 1, a + 1, b + 1, b + 1, c + 1, c + 1), E'\n' ORDER BY i)
      FROM faces) || E'\n', 'UTF8');
-- GLB: a JSON chunk and a BIN chunk (positions, then 32-bit indices).
WITH bin AS (
  SELECT (SELECT string_agg(pg_temp.f32(x) || pg_temp.f32(y) || pg_temp.f32(z), ''::bytea ORDER BY i) FROM verts) AS pos,
         (SELECT string_agg(pg_temp.u32(a) || pg_temp.u32(b) || pg_temp.u32(c), ''::bytea ORDER BY i) FROM faces) AS idx
), box AS (
  SELECT min(x::float4) AS x0, min(y::float4) AS y0, min(z::float4) AS z0,
         max(x::float4) AS x1, max(y::float4) AS y1, max(z::float4) AS z1 FROM verts
), json AS (
  SELECT rpad(j, (length(j) + 3) / 4 * 4, ' ') AS j, bin.pos || bin.idx AS b
  FROM bin, box, counts, LATERAL (SELECT format(
    '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],'
    '"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],'
    '"accessors":[{"bufferView":0,"componentType":5126,"count":%s,"type":"VEC3","min":[%s,%s,%s],"max":[%s,%s,%s]},'
    '{"bufferView":1,"componentType":5125,"count":%s,"type":"SCALAR"}],'
    '"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":%s},{"buffer":0,"byteOffset":%s,"byteLength":%s}],'
    '"buffers":[{"byteLength":%s}]}',
    nv, x0, y0, z0, x1, y1, z1, 3 * nf, length(bin.pos), length(bin.pos), length(bin.idx),
    length(bin.pos) + length(bin.idx)) AS j) s
)
INSERT INTO valid SELECT 'GLB',
  convert_to('glTF', 'UTF8') || pg_temp.u32(2) || pg_temp.u32(12 + 8 + length(j) + 8 + length(b))
  || pg_temp.u32(length(j)) || convert_to('JSON', 'UTF8') || convert_to(j, 'UTF8')
  || pg_temp.u32(length(b)) || '\x42494e00'::bytea || b
FROM json;
-- An 8 x 8 BMP (24 bits, rows padded to 4 bytes) and an 8 x 8 TGA (24 bits, uncompressed).
INSERT INTO valid SELECT 'BMP', convert_to('BM', 'UTF8') || pg_temp.u32(54 + 192) || pg_temp.u32(0)
  || pg_temp.u32(54) || pg_temp.u32(40) || pg_temp.u32(8) || pg_temp.u32(8) || pg_temp.u16(1)
  || pg_temp.u16(24) || pg_temp.u32(0) || pg_temp.u32(192) || pg_temp.u32(2835) || pg_temp.u32(2835)
  || pg_temp.u32(0) || pg_temp.u32(0) || pg_temp.noise('bmp pixels', 192);
INSERT INTO valid SELECT 'TGA', '\x000002000000000000000000'::bytea || pg_temp.u16(8) || pg_temp.u16(8)
  || '\x1800'::bytea || pg_temp.noise('tga pixels', 192);

-- Value pools, by type and class --------------------------------------------------------------
-- pool: one row per value; calls read it back with a scalar subquery, so each value keeps its
-- type (and an arg its out-of-line storage, as in a table).
CREATE TEMP TABLE pool (
  id serial PRIMARY KEY, typ regtype NOT NULL, class text NOT NULL, label text NOT NULL,
  v_bytea bytea, v_text text, v_int4 int4, v_int8 int8, v_float8 float8, v_float4 float4,
  v_bool bool, v_arg arg, v_weights arg_weights, v_jsonb jsonb, v_name name, v_sketch arg_sketch,
  v_regclass regclass,
  v_sql text  -- an expression instead of a stored value (polymorphic arguments)
);
CREATE FUNCTION pg_temp.column_of(t regtype) RETURNS text LANGUAGE sql IMMUTABLE AS $$
  SELECT CASE t WHEN 'bytea'::regtype THEN 'v_bytea' WHEN 'text'::regtype THEN 'v_text'
                WHEN 'integer'::regtype THEN 'v_int4' WHEN 'bigint'::regtype THEN 'v_int8'
                WHEN 'double precision'::regtype THEN 'v_float8' WHEN 'real'::regtype THEN 'v_float4'
                WHEN 'boolean'::regtype THEN 'v_bool' WHEN 'arg'::regtype THEN 'v_arg'
                WHEN 'arg_weights'::regtype THEN 'v_weights' WHEN 'jsonb'::regtype THEN 'v_jsonb'
                WHEN 'name'::regtype THEN 'v_name' WHEN 'anyelement'::regtype THEN 'v_sql'
                WHEN 'arg_sketch'::regtype THEN 'v_sketch' WHEN 'regclass'::regtype THEN 'v_regclass' END $$;
-- The SQL expression for pool value `id`.
CREATE FUNCTION pg_temp.value_sql(id int) RETURNS text LANGUAGE sql STABLE AS $$
  SELECT coalesce(v_sql, format('(SELECT %s FROM pg_temp.pool WHERE id = %s)', pg_temp.column_of(typ), id))
  FROM pg_temp.pool p WHERE p.id = value_sql.id $$;

-- A table for the functions that take a table's row type (anyelement) and a column name.
CREATE TEMP TABLE knn_objects (id int, museum text, descr arg);
-- And an arg_ivf index on it, for the functions that take an index.
CREATE INDEX knn_objects_descr ON knn_objects USING arg_ivf (descr);
CREATE INDEX knn_objects_id ON knn_objects (id);

-- Valid values: candidates for the arguments that are not the hostile one.
INSERT INTO pool (typ, class, label, v_bytea) SELECT 'bytea', 'valid', name, bytes FROM valid
  WHERE name IN ('OFF', 'OBJ (textured)', 'BMP');
INSERT INTO pool (typ, class, label, v_text) VALUES ('text', 'valid', '''''', ''), ('text', 'valid', 'cup', 'cup');
INSERT INTO pool (typ, class, label, v_int4) VALUES ('integer', 'valid', '0', 0), ('integer', 'valid', '8', 8),
  ('integer', 'valid', '2', 2);
INSERT INTO pool (typ, class, label, v_int8) VALUES ('bigint', 'valid', '0', 0);
INSERT INTO pool (typ, class, label, v_float8) VALUES ('double precision', 'valid', '0.5', 0.5);
INSERT INTO pool (typ, class, label, v_float4) VALUES ('real', 'valid', '0.5', 0.5);
INSERT INTO pool (typ, class, label, v_bool) VALUES ('boolean', 'valid', 'true', true);
INSERT INTO pool (typ, class, label, v_arg) SELECT 'arg', 'valid', 'the cup', arg_build(off) FROM model;
INSERT INTO pool (typ, class, label, v_weights) VALUES ('arg_weights', 'valid', 'arg', 'arg');
INSERT INTO pool (typ, class, label, v_sketch) SELECT 'arg_sketch', 'valid', 'the cup''s sketch', arg_sketch(arg_build(off)) FROM model;
INSERT INTO pool (typ, class, label, v_jsonb) VALUES ('jsonb', 'valid', '{}', '{}');
INSERT INTO pool (typ, class, label, v_name) VALUES ('name', 'valid', 'descr', 'descr');
INSERT INTO pool (typ, class, label, v_sql) VALUES ('anyelement', 'valid', 'a table''s row type', 'NULL::pg_temp.knn_objects');
INSERT INTO pool (typ, class, label, v_regclass) VALUES ('regclass', 'valid', 'an arg_ivf index', 'pg_temp.knn_objects_descr');

-- NULL of every type.
INSERT INTO pool (typ, class, label)
SELECT t::regtype, 'NULL', 'NULL' FROM unnest(ARRAY['bytea', 'text', 'integer', 'bigint', 'double precision',
  'real', 'boolean', 'arg', 'arg_weights', 'jsonb', 'name', 'arg_sketch', 'regclass']) t;
INSERT INTO pool (typ, class, label, v_sql) VALUES ('anyelement', 'NULL', 'NULL::text', 'NULL::text');

-- Empty values.
INSERT INTO pool (typ, class, label, v_bytea) VALUES ('bytea', 'empty', 'empty bytea', '');
INSERT INTO pool (typ, class, label, v_text) VALUES ('text', 'empty', 'empty text', ''),
  ('text', 'empty', 'blanks', E' \t\n,');
INSERT INTO pool (typ, class, label, v_int4) VALUES ('integer', 'empty', '0', 0);
INSERT INTO pool (typ, class, label, v_int8) VALUES ('bigint', 'empty', '0', 0);
INSERT INTO pool (typ, class, label, v_float8) VALUES ('double precision', 'empty', '0', 0);
INSERT INTO pool (typ, class, label, v_float4) VALUES ('real', 'empty', '0', 0);
INSERT INTO pool (typ, class, label, v_jsonb) VALUES ('jsonb', 'empty', '{}', '{}'), ('jsonb', 'empty', '[]', '[]');
INSERT INTO pool (typ, class, label, v_name) VALUES ('name', 'empty', 'empty name', '');

-- Random bytes: plain, and behind each format's magic so that the readers go past detection.
INSERT INTO pool (typ, class, label, v_bytea)
SELECT 'bytea', 'random', format('%s bytes of noise', n), pg_temp.noise('plain ' || n, n)
FROM unnest(ARRAY[1, 3, 7, 16, 84, 255, 1000, 4096, 65536]) n;
INSERT INTO pool (typ, class, label, v_bytea)
SELECT 'bytea', 'random', format('%s then %s bytes of noise', label, n), convert_to(magic, 'UTF8') || pg_temp.noise(label || n, n)
FROM (VALUES ('OFF', E'OFF\n'), ('OFF counts', E'OFF\n3 1 0\n'), ('OFF huge counts', E'OFF\n3999999 7999999 0\n'),
             ('PLY', E'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'),
             ('PLY ASCII', E'ply\nformat ascii 1.0\nelement vertex 100000000\nproperty double x\nend_header\n'),
             ('STL', 'solid x'), ('OBJ', E'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 '), ('GLB', 'glTF'),
             ('BMP', 'BM'), ('glTF JSON', '{"asset":{"version":"2.0"},')) m(label, magic),
     unnest(ARRAY[16, 100, 3000]) n;
-- PNG, JPEG and TGA headers are not UTF-8 text: written as bytes.
INSERT INTO pool (typ, class, label, v_bytea)
SELECT 'bytea', 'random', format('%s magic then %s bytes of noise', label, n), magic || pg_temp.noise(label || n, n)
FROM (VALUES ('PNG', '\x89504e470d0a1a0a'::bytea), ('JPEG', '\xffd8ffe0'::bytea),
             ('TGA header', '\x000002000000000000000000ffffffff1800'::bytea)) m(label, magic),
     unnest(ARRAY[16, 100, 3000]) n;
-- A binary STL whose count promises a billion triangles, a GLB whose chunk claims 4 GB.
INSERT INTO pool (typ, class, label, v_bytea) VALUES
  ('bytea', 'random', 'binary STL claiming 1e9 triangles', convert_to(rpad('x', 80), 'UTF8') || pg_temp.u32(1000000000) || pg_temp.noise('stl', 500)),
  ('bytea', 'random', 'GLB claiming a 2 GB chunk', convert_to('glTF', 'UTF8') || pg_temp.u32(2) || pg_temp.u32(2000000000)
     || pg_temp.u32(2000000000) || convert_to('JSON{}', 'UTF8'));
-- Random text: printable noise, noise with separators and '=', long text, non-ASCII.
INSERT INTO pool (typ, class, label, v_text)
SELECT 'text', 'random', format('%s characters of base64 noise', n), encode(pg_temp.noise('text ' || n, n), 'base64')
FROM unnest(ARRAY[3, 40, 5000]) n;
INSERT INTO pool (typ, class, label, v_text) VALUES
  ('text', 'random', 'key=value noise', 'levels=9999999999999999999 mu= =x base_points=-1 threads=1e9 levels=nan'),
  ('text', 'random', 'repeated pairs', repeat('levels=3 ', 2000)),
  ('text', 'random', 'non-ASCII', 'ünïcødé ☃ levels=３'),
  ('text', 'random', 'quotes and backslashes', E'\\''"\\\\ %s %n {}[]');
INSERT INTO pool (typ, class, label, v_int4)
SELECT 'integer', 'random', n::text, n FROM unnest(ARRAY[-2147483648, -1, 1, 7, 99, 129, 4096, 999999, 1000000, 2147483647]) n;
INSERT INTO pool (typ, class, label, v_int8)
SELECT 'bigint', 'random', n::text, n FROM unnest(ARRAY[-9223372036854775808, -1, 9223372036854775807]) n;
INSERT INTO pool (typ, class, label, v_float8)
SELECT 'double precision', 'random', n::text, n FROM unnest(ARRAY['NaN', 'Infinity', '-Infinity', '-1', '1e308']::float8[]) n;
INSERT INTO pool (typ, class, label, v_float4)
SELECT 'real', 'random', n::text, n FROM unnest(ARRAY['NaN', 'Infinity', '-1', '3e38']::float4[]) n;
INSERT INTO pool (typ, class, label, v_bool) VALUES ('boolean', 'random', 'false', false);
INSERT INTO pool (typ, class, label, v_name)
SELECT 'name', 'random', n, n FROM unnest(ARRAY['nope', 'id', 'museum', 'descr"; DROP TABLE knn_objects; --',
  'DESCR', repeat('d', 100)]) n;
INSERT INTO pool (typ, class, label, v_jsonb)
SELECT 'jsonb', 'random', left(j, 60), j::jsonb FROM unnest(ARRAY['"x"', '1', 'null', '{"nope": 1}', '{"id": "x"}',
  '{"museum": null}', '{"museum": "M1", "id": 3}', '{"museum": "x'' OR true --"}', '{"descr\" IS NULL OR \"x": 1}',
  repeat('[', 1000) || repeat(']', 1000),
  (SELECT '{' || string_agg(format('"k%s": %s', i, i), ',') || '}' FROM generate_series(1, 2000) i)]) j;
INSERT INTO pool (typ, class, label, v_regclass) VALUES
  ('regclass', 'random', 'a table', 'pg_temp.knn_objects'), ('regclass', 'random', 'a B-tree index', 'pg_temp.knn_objects_id'),
  ('regclass', 'random', 'a catalogue', 'pg_class'), ('regclass', 'random', 'OID 0', 0),
  ('regclass', 'random', 'an OID of nothing', 4000000000);
INSERT INTO pool (typ, class, label, v_sql)
SELECT 'anyelement', 'random', e, e FROM unnest(ARRAY['NULL::int', '42', '''x''::text', 'NULL::pg_temp.pool',
  'ROW(1, 2)', 'NULL::pg_class']) e;

-- Truncated valid inputs: every format cut at a spread of lengths (the first bytes, the middle,
-- one byte short).
INSERT INTO pool (typ, class, label, v_bytea)
SELECT DISTINCT ON (name, cut) 'bytea', 'truncated', format('%s cut to %s of %s bytes', name, cut, length(bytes)),
       substr(bytes, 1, cut)
FROM valid, LATERAL unnest(ARRAY[1, 2, 4, 5, 12, 20, 54, 60, 84, 100, 134, 300,
                                 length(bytes) / 3, length(bytes) / 2, length(bytes) * 9 / 10,
                                 length(bytes) - 4, length(bytes) - 1]) cut
WHERE cut BETWEEN 1 AND length(bytes) - 1;
INSERT INTO pool (typ, class, label, v_text)
SELECT 'text', 'truncated', format('%L', t), t
FROM (SELECT left('levels=5 mu=geodesic base_points=128 threads=2', n) AS t FROM generate_series(1, 46, 3) n
      UNION SELECT left('octopus', n) FROM generate_series(1, 6) n) s;

-- Weights: every preset, alone and with a change; extreme but valid weights.
INSERT INTO pool (typ, class, label, v_weights)
SELECT 'arg_weights', 'weights presets', w, w::arg_weights
FROM unnest(ARRAY['arg', 'mrg', 'shape', 'colour', 'mrg norm=l2', 'shape groups=on tung=off',
                  'colour lambda_4=0.5']) w;
INSERT INTO pool (typ, class, label, v_weights)
SELECT 'arg_weights', 'extreme weights', w, w::arg_weights
FROM unnest(ARRAY['alpha_l=0 beta_l=0 gamma_l=0 delta_l=0 eps_l=0',
                  'alpha_s=0 beta_s=0 lambda_1=0 lambda_2=0 lambda_3=0 lambda_4=1e-30',
                  'alpha_l=1e6 beta_l=1e6 gamma_l=1e6 delta_l=1e6 eps_l=1e6 alpha_s=1e6 beta_s=1e6 lambda_1=1e6 lambda_2=1e6 lambda_3=1e6 lambda_4=1e6',
                  'alpha_l=1e-38 alpha_s=1e-38 beta_s=0 lambda_1=0 lambda_2=0 lambda_3=0 lambda_4=0 norm=l2 groups=on']) w;

-- Unusual valid ARGs: one level, the most levels, other mu kinds, the fewest base points, a
-- tetrahedron, a single open triangle, two components, a torus, textured colour.
INSERT INTO pool (typ, class, label, v_arg)
SELECT 'arg', 'unusual', label, arg_build(mesh, opts)
FROM model, LATERAL (VALUES
  ('cup, levels=1', off, 'levels=1'), ('cup, levels=7', off, 'levels=7'),
  ('cup, mu=height', off, 'mu=height'), ('cup, mu=centroid base_points=8', off, 'mu=centroid base_points=8'),
  ('tetrahedron', convert_to(E'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n', 'UTF8'), ''),
  ('one open triangle', convert_to(E'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n', 'UTF8'), 'levels=2'),
  ('two tetrahedra', convert_to(E'OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n6 5 5\n5 6 5\n5 5 6\n'
                                 '3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n', 'UTF8'), ''),
  ('torus', arg_generate_model('torus', 3, 8), '')) AS t(label, mesh, opts);
INSERT INTO pool (typ, class, label, v_arg)
SELECT 'arg', 'unusual', 'textured OBJ with a BMP', arg_build(m.bytes, t.bytes)
FROM valid m, valid t WHERE m.name = 'OBJ (textured)' AND t.name = 'BMP';
INSERT INTO knn_objects SELECT id, 'M' || id % 2, v_arg FROM pool WHERE typ = 'arg'::regtype AND class IN ('valid', 'unusual');
-- Their sketches (some without a spectrum or a panorama part).
INSERT INTO pool (typ, class, label, v_sketch)
SELECT 'arg_sketch', 'unusual', label || '''s sketch', arg_sketch(v_arg) FROM pool
WHERE typ = 'arg'::regtype AND class = 'unusual';

-- Forged ARG values (superuser only): bytes relabelled as arg without input validation, as a
-- corrupted data file or a careless C function could hand over. They skip the checks that
-- input makes, so the functions must still be safe with what their readers do check.
CREATE TEMP TABLE forged_ok AS SELECT rolsuper AS yes FROM pg_roles WHERE rolname = current_user;
DO $$ BEGIN
  IF (SELECT yes FROM forged_ok) THEN
    CREATE CAST (bytea AS arg) WITHOUT FUNCTION;
    CREATE CAST (bytea AS arg_sketch) WITHOUT FUNCTION;
  END IF;
END $$;
CREATE TEMP TABLE forged (label text, bytes bytea);
INSERT INTO forged
SELECT format('cup binary form cut to %s of %s bytes', cut, length(b)), substr(b, 1, cut)
FROM (SELECT arg_send(v_arg) AS b FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype) s,
     unnest(ARRAY[0, 1, 4, 24, 100, 300, 500, 1000, 5000]) cut WHERE cut < length(b);
-- Every third 4-byte word of the header and of the first node replaced by NaN, -1 and a huge
-- count; then 64 deterministic bytes anywhere flipped.
INSERT INTO forged
SELECT format('cup with bytes %s..%s set to %s', at, at + 3, label), overlay(b PLACING word FROM at FOR 4)
FROM (SELECT arg_send(v_arg) AS b FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype) s,
     (VALUES ('NaN', '\x0000c07f'::bytea), ('-1', '\xffffffff'::bytea), ('2^30', '\x00000040'::bytea)) w(label, word),
     generate_series(1, 620, 12) at;
INSERT INTO forged
SELECT format('cup with byte %s flipped', at), set_byte(b, at, get_byte(b, at) # 255)
FROM (SELECT arg_send(v_arg) AS b FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype) s,
     LATERAL (SELECT (('x' || substr(md5('flip' || k), 1, 8))::bit(32)::bigint % length(b))::int AS at
              FROM generate_series(1, 64) k) p;
INSERT INTO forged SELECT format('%s bytes of noise', n), pg_temp.noise('forged ' || n, n) FROM unnest(ARRAY[3, 64, 4000]) n;
DO $$ BEGIN
  IF (SELECT yes FROM forged_ok) THEN
    EXECUTE 'INSERT INTO pg_temp.pool (typ, class, label, v_arg) SELECT ''arg'', ''forged'', label, bytes::arg FROM pg_temp.forged';
  END IF;
END $$;
-- Forged sketches: the cup's cut short, words set to NaN, -1 and a huge value, bytes flipped.
CREATE TEMP TABLE forged_sketch (label text, bytes bytea);
INSERT INTO forged_sketch
SELECT format('sketch cut to %s of %s bytes', cut, length(b)), substr(b, 1, cut)
FROM (SELECT arg_sketch_send(v_sketch) AS b FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype) s,
     unnest(ARRAY[0, 1, 4, 8, 100, 192, 300, 2000, 2500]) cut WHERE cut < length(b);
INSERT INTO forged_sketch
SELECT format('sketch with bytes %s..%s set to %s', at, at + 3, label), overlay(b PLACING word FROM at FOR 4)
FROM (SELECT arg_sketch_send(v_sketch) AS b FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype) s,
     (VALUES ('NaN', '\x0000c07f'::bytea), ('-1', '\xffffffff'::bytea), ('2^30', '\x00000040'::bytea)) w(label, word),
     generate_series(1, 2600, 97) at;
INSERT INTO forged_sketch
SELECT format('sketch with byte %s flipped', at), set_byte(b, at, get_byte(b, at) # 255)
FROM (SELECT arg_sketch_send(v_sketch) AS b FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype) s,
     LATERAL (SELECT (('x' || substr(md5('sketch flip' || k), 1, 8))::bit(32)::bigint % length(b))::int AS at
              FROM generate_series(1, 64) k) p;
INSERT INTO forged_sketch SELECT format('%s bytes of noise', n), pg_temp.noise('forged sketch ' || n, n) FROM unnest(ARRAY[3, 64, 2592]) n;
DO $$ BEGIN
  IF (SELECT yes FROM forged_ok) THEN
    EXECUTE 'INSERT INTO pg_temp.pool (typ, class, label, v_sketch) SELECT ''arg_sketch'', ''forged'', label, bytes::arg_sketch FROM pg_temp.forged_sketch';
  END IF;
END $$;

-- The calls ----------------------------------------------------------------------------------

-- Every function of the extension, except the type I/O functions (cstring and internal
-- arguments, tested below through casts and COPY) and the trigger (below).
CREATE TEMP TABLE funcs AS
SELECT p.oid, p.oid::regprocedure::text AS sig, p.proname::text AS name, p.proretset AS set_returning,
       p.proisstrict AS is_strict,
       ARRAY(SELECT t FROM unnest(p.proargtypes::regtype[]) WITH ORDINALITY u(t, k) ORDER BY k) AS argtypes
FROM pg_proc p
JOIN pg_depend d ON d.objid = p.oid AND d.classid = 'pg_proc'::regclass AND d.deptype = 'e'
JOIN pg_extension e ON e.oid = d.refobjid AND e.extname = 'arg'
WHERE NOT ('cstring'::regtype = ANY (p.proargtypes::regtype[]) OR 'internal'::regtype = ANY (p.proargtypes::regtype[]))
  AND p.prorettype <> 'trigger'::regtype AND p.prokind = 'f';

-- The SQL of one call of f with arguments `ids` (pool ids).
CREATE FUNCTION pg_temp.call_sql(f oid, ids int[]) RETURNS text LANGUAGE sql STABLE AS $$
  SELECT CASE WHEN fn.set_returning
              THEN format('SELECT count(*)::text FROM %s(%s) s', fn.name, args)
              ELSE format('SELECT (%s(%s))::text', fn.name, args) END
  FROM pg_temp.funcs fn,
       LATERAL (SELECT coalesce(string_agg(pg_temp.value_sql(i), ', ' ORDER BY k), '') AS args
                FROM unnest(ids) WITH ORDINALITY AS u(i, k)) a
  WHERE fn.oid = f $$;

-- For each function, the first combination of valid values that it accepts: the baseline that
-- a hostile argument replaces. NULL is a candidate too (for optional arguments) but only for a
-- function that is not STRICT, and combinations with fewer NULLs come first.
CREATE TEMP TABLE baseline (oid oid PRIMARY KEY, ids int[]);
DO $$
DECLARE
  fn record;
  combo int[];
  done bool;
BEGIN
  FOR fn IN SELECT * FROM pg_temp.funcs LOOP
    done := false;
    FOR combo IN
      WITH RECURSIVE c(k, ids, nulls) AS (
        SELECT 0, '{}'::int[], 0
        UNION ALL
        SELECT c.k + 1, c.ids || p.id, c.nulls + (p.class = 'NULL')::int
        FROM c JOIN pg_temp.pool p ON p.typ = fn.argtypes[c.k + 1]
          AND (p.class = 'valid' OR (p.class = 'NULL' AND NOT fn.is_strict))
        WHERE c.k < cardinality(fn.argtypes))
      SELECT ids FROM c WHERE k = cardinality(fn.argtypes) ORDER BY nulls, ids LIMIT 200
    LOOP
      IF (pg_temp.attempt(pg_temp.call_sql(fn.oid, combo))).state = '00000' THEN
        INSERT INTO pg_temp.baseline VALUES (fn.oid, combo);
        done := true;
        EXIT;
      END IF;
    END LOOP;
  END LOOP;
END $$;

-- One case per function and class: every value of the class in each argument position in turn.
-- Allowed SQLSTATEs: success, a data exception (class 22), a bad name or type given to a
-- function that takes one (class 42), over a cap (54000); for forged values also XX001 (data
-- corrupted) and a NaN result (a forged value's NaN feature flows into its SIM).
CREATE TEMP TABLE cases (n serial, description text, queries text[], allowed text, nan_ok bool DEFAULT false);
INSERT INTO cases (description, queries, allowed, nan_ok)
SELECT format('%s with %s arguments', f.sig, cls.class),
       array_agg(pg_temp.call_sql(f.oid, b.ids[:k - 1] || p.id || b.ids[k + 1:]) ORDER BY k, p.id),
       CASE WHEN cls.class = 'forged' THEN '^(00000|22...|42...|54000|XX001)$' ELSE '^(00000|22...|42...|54000)$' END,
       cls.class = 'forged'
FROM funcs f JOIN baseline b USING (oid)
CROSS JOIN (VALUES (1, 'NULL'), (2, 'empty'), (3, 'random'), (4, 'truncated'), (5, 'weights presets'),
                   (6, 'extreme weights'), (7, 'unusual'), (8, 'forged')) cls(ord, class)
JOIN LATERAL generate_subscripts(f.argtypes, 1) k ON true
JOIN pool p ON p.typ = f.argtypes[k] AND p.class = cls.class
GROUP BY f.sig, cls.ord, cls.class
ORDER BY f.sig, cls.ord;
-- Functions without arguments: called once.
INSERT INTO cases (description, queries, allowed)
SELECT format('%s answers', f.sig), ARRAY[pg_temp.call_sql(f.oid, '{}')], '^00000$'
FROM funcs f WHERE cardinality(f.argtypes) = 0 ORDER BY f.sig;
-- Functions of two ARGs over every pair of ARG values in one statement: the query cache sees
-- values change, repeat and alternate from row to row. Forged values are paired with the valid
-- and unusual ones.
INSERT INTO cases (description, queries, allowed, nan_ok)
SELECT format('%s over every pair of %s ARGs in one statement', f.sig, cls), ARRAY[
  format('SELECT count(*)::text FROM pg_temp.pool a, pg_temp.pool b WHERE a.typ = ''arg''::regtype '
         'AND b.typ = ''arg''::regtype AND a.class IN (%s) AND b.class IN (''valid'', ''unusual'') AND %s',
         a_classes,
         CASE WHEN f.set_returning THEN format('EXISTS (SELECT FROM %s(a.v_arg, b.v_arg%s))', f.name, extra)
              ELSE format('%s(a.v_arg, b.v_arg%s) IS NOT NULL', f.name, extra) END)],
  CASE WHEN cls = 'forged' THEN '^(00000|22...|54000|XX001)$' ELSE '^(00000|22...|54000)$' END, cls = 'forged'
FROM funcs f, (VALUES ('valid and unusual', '''valid'', ''unusual'''), ('forged', '''forged''')) c(cls, a_classes),
     LATERAL (SELECT CASE WHEN cardinality(f.argtypes) = 3 THEN ', ''arg''' ELSE '' END AS extra) x
WHERE f.argtypes[1:2] = ARRAY['arg', 'arg']::regtype[]
  AND (cardinality(f.argtypes) = 2 OR f.argtypes[3] = 'arg_weights'::regtype)
  AND (cls <> 'forged' OR (SELECT yes FROM forged_ok))
ORDER BY f.sig, cls;

-- Every operator of the extension, with NULL, unusual and forged operands on either side.
INSERT INTO cases (description, queries, allowed, nan_ok)
SELECT format('operator %s with %s operands', o.oid::regoperator, cls.class),
       array_agg(format('SELECT (%s %s %s)::text', l, o.oprname, r) ORDER BY p.id, side),
       CASE WHEN cls.class = 'forged' THEN '^(00000|22...|42...|54000|XX001)$' ELSE '^(00000|22...|42...|54000)$' END,
       cls.class = 'forged'
FROM pg_operator o
JOIN pg_depend d ON d.objid = o.oid AND d.classid = 'pg_operator'::regclass AND d.deptype = 'e'
JOIN pg_extension e ON e.oid = d.refobjid AND e.extname = 'arg'
CROSS JOIN (VALUES (1, 'NULL'), (2, 'unusual'), (3, 'forged')) cls(ord, class)
JOIN pool p ON p.class = cls.class AND p.typ = 'arg'::regtype
CROSS JOIN LATERAL (VALUES (1, pg_temp.value_sql(p.id), '(SELECT v_arg FROM pg_temp.pool WHERE class = ''valid'' AND typ = ''arg''::regtype)'),
                           (2, '(SELECT v_arg FROM pg_temp.pool WHERE class = ''valid'' AND typ = ''arg''::regtype)', pg_temp.value_sql(p.id))) s(side, l, r)
WHERE o.oprleft = 'arg'::regtype AND o.oprright = 'arg'::regtype
GROUP BY o.oid, cls.ord, cls.class
ORDER BY o.oid::regoperator::text, cls.ord;

-- Type input. arg text: empty, noise, base64 noise behind the tag, the valid text cut at many
-- lengths (whole base64 quanta too, so decoding succeeds and validation must catch it), one
-- character changed, padding misplaced.
CREATE TEMP TABLE arg_text AS SELECT v_arg::text AS t FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_in (text to arg) with hostile text', array_agg(format('SELECT %L::arg::text IS NOT NULL', t) ORDER BY n),
       '^(00000|22P02)$'
FROM (SELECT 1 AS n, '' AS t UNION ALL SELECT 2, 'arg1:' UNION ALL SELECT 3, 'arg1:=' UNION ALL SELECT 4, 'arg1:===='
      UNION ALL SELECT 5, 'arg1:QUJD====' UNION ALL SELECT 6, 'ARG1:' || substr(t, 6) FROM arg_text
      UNION ALL SELECT 7, 'arg1:' || repeat('A', 4 * 100000)
      UNION ALL SELECT 10 + n, 'arg1:' || encode(pg_temp.noise('arg text ' || n, n * 3), 'base64') FROM generate_series(1, 20) n
      UNION ALL SELECT 40 + k, 'arg1:' || replace(encode(substr(decode(substr(t, 6), 'base64'), 1, cut), 'base64'), E'\n', '')
        FROM arg_text, unnest(ARRAY[1, 2, 3, 4, 8, 16, 24, 25, 100, 299, 300, 301, 1000, 4000, 8000, 12000]) WITH ORDINALITY u(cut, k)
      UNION ALL SELECT 100 + cut, left(t, cut) FROM arg_text, unnest(ARRAY[4, 5, 6, 9, 10, 100, 401, 4001, 9999]) cut
      UNION ALL SELECT 200 + k, overlay(t PLACING CASE WHEN substr(t, at, 1) = 'A' THEN 'B' ELSE 'A' END FROM at FOR 1)
        FROM arg_text, generate_series(1, 40) k,
             LATERAL (SELECT (('x' || substr(md5('char' || k), 1, 6))::bit(24)::int % (length(t) - 6)) + 6 AS at) p
      UNION ALL SELECT 300, t || '=' FROM arg_text UNION ALL SELECT 301, t || E'\n' FROM arg_text
      UNION ALL SELECT 302, t || t FROM arg_text UNION ALL SELECT 303, ' ' || t FROM arg_text) s;
-- arg_sketch text: empty, the wrong tag, noise, the valid text cut and with a character changed.
CREATE TEMP TABLE sketch_text AS SELECT v_sketch::text AS t FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_sketch_in (text to arg_sketch) with hostile text',
       array_agg(format('SELECT %L::arg_sketch::text IS NOT NULL', t) ORDER BY n), '^(00000|22P02)$'
FROM (SELECT 1 AS n, '' AS t UNION ALL SELECT 2, 'sketch1:' UNION ALL SELECT 3, 'sketch1:===='
      UNION ALL SELECT 4, 'arg1:' || substr(t, 9) FROM sketch_text
      UNION ALL SELECT 10 + n, 'sketch1:' || encode(pg_temp.noise('sketch text ' || n, n * 3), 'base64') FROM generate_series(1, 20) n
      UNION ALL SELECT 40 + k, 'sketch1:' || replace(encode(substr(decode(substr(t, 9), 'base64'), 1, cut), 'base64'), E'\n', '')
        FROM sketch_text, unnest(ARRAY[1, 3, 4, 8, 9, 100, 192, 300, 2000, 2591]) WITH ORDINALITY u(cut, k)
      UNION ALL SELECT 100 + k, overlay(t PLACING CASE WHEN substr(t, at, 1) = 'A' THEN 'B' ELSE 'A' END FROM at FOR 1)
        FROM sketch_text, generate_series(1, 40) k,
             LATERAL (SELECT (('x' || substr(md5('sketch char' || k), 1, 6))::bit(24)::int % (length(t) - 9)) + 9 AS at) p
      UNION ALL SELECT 200, t || t FROM sketch_text UNION ALL SELECT 201, ' ' || t FROM sketch_text) s;
-- arg_weights text: malformed weights.
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_weights_in (text to arg_weights) with malformed weights',
       array_agg(format('SELECT %L::arg_weights::text', w) ORDER BY w), '^(00000|22P02)$'
FROM unnest(ARRAY['', ' ', 'arg mrg', 'no_such_preset', 'alpha_l', 'alpha_l=', '=1', '=', 'alpha_l==1',
                  'alpha_l=1=2', 'alpha_l=-1', 'alpha_l=1e7', 'alpha_l=1e400', 'alpha_l=nan', 'alpha_l=inf',
                  'alpha_l=0x10', 'alpha_l=1,5', 'alpha_l= 1', 'lambda_9=1', 'lambda_0=1', 'norm=l3', 'norm=',
                  'tung=maybe', 'groups=2', 'alpha_l=1 alpha_l=2', 'arg arg', 'ARG', 'mrg alpha_l=.5 shape',
                  'alpha_s=0 beta_s=0 lambda_1=0 lambda_2=0 lambda_3=0 lambda_4=0',
                  repeat('alpha_l=0.5 ', 1000), repeat('x', 100000), E'arg\x01', 'ärg', 'arg;DROP TABLE x']) w;
-- Type binary input through COPY (FORMAT binary): the file is written next to the data and read
-- back into a one-column table, so arg_recv and arg_weights_recv see the bytes as a client's.
CREATE TEMP TABLE recv_arg (v arg);
CREATE TEMP TABLE recv_weights (v arg_weights);
CREATE TEMP TABLE recv_sketch (v arg_sketch);
CREATE FUNCTION pg_temp.copy_in(target text, payload bytea) RETURNS text LANGUAGE plpgsql AS $$
DECLARE
  file text := 'arg_no_crash_' || pg_backend_pid() || '.copy';
  lo oid;
BEGIN
  lo := lo_from_bytea(0, '\x5047434f50590aff0d0a00'::bytea || int4send(0) || int4send(0)
                         || int2send(1::int2) || int4send(length(payload)) || payload || int2send(-1::int2));
  PERFORM lo_export(lo, file);
  PERFORM lo_unlink(lo);
  EXECUTE format('COPY %s FROM %L (FORMAT binary)', target, file);
  RETURN 'copied';
END $$;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_recv (binary COPY of arg) with truncated, corrupted and random bytes',
       array_agg(format('SELECT pg_temp.copy_in(''recv_arg'', %L::bytea)', b) ORDER BY n), '^(00000|22P03)$'
FROM (SELECT 0 AS n, arg_send(v_arg) AS b FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype
      UNION ALL SELECT 1, ''::bytea
      UNION ALL SELECT 10 + k, substr(arg_send(v_arg), 1, cut) FROM pool, unnest(ARRAY[1, 4, 23, 24, 300, 301, 1000, 5000])
        WITH ORDINALITY u(cut, k) WHERE class = 'valid' AND typ = 'arg'::regtype
      UNION ALL SELECT 30 + k, set_byte(b, at, get_byte(b, at) # 1)
        FROM (SELECT arg_send(v_arg) AS b FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype) s,
             LATERAL (SELECT k, (('x' || substr(md5('bit' || k), 1, 8))::bit(32)::bigint % length(b))::int AS at
                      FROM generate_series(1, 40) k) p
      UNION ALL SELECT 100 + n, pg_temp.noise('recv ' || n, n * 37) FROM generate_series(1, 10) n
      UNION ALL SELECT 200, arg_send(v_arg) || '\x00'::bytea FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype) s;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_weights_recv (binary COPY of arg_weights) with short, long and invalid values',
       array_agg(format('SELECT pg_temp.copy_in(''recv_weights'', %L::bytea)', b) ORDER BY n), '^(00000|22P03|08P01)$'
FROM (SELECT n, pg_temp.noise('weights ' || n, n) AS b FROM generate_series(0, 50, 5) n
      UNION ALL SELECT 100, arg_weights_send('arg') || '\x00'::bytea
      UNION ALL SELECT 101, substr(arg_weights_send('arg'), 1, 44)
      UNION ALL SELECT 102, overlay(arg_weights_send('arg') PLACING '\x7fc00000'::bytea FROM 1 FOR 4)
      UNION ALL SELECT 103, overlay(arg_weights_send('arg') PLACING '\xbf800000'::bytea FROM 5 FOR 4)
      UNION ALL SELECT 104, overlay(arg_weights_send('arg') PLACING '\x7f800000'::bytea FROM 41 FOR 4)
      UNION ALL SELECT 105, overlay(arg_weights_send('arg') PLACING '\xff'::bytea FROM 45 FOR 1)
      UNION ALL SELECT 106, overlay(arg_weights_send('arg') PLACING '\x00000000000000000000000000000000'::bytea FROM 21 FOR 16)
      UNION ALL SELECT 107, arg_weights_send('mrg')) s;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_sketch_recv (binary COPY of arg_sketch) with truncated, corrupted and random bytes',
       array_agg(format('SELECT pg_temp.copy_in(''recv_sketch'', %L::bytea)', b) ORDER BY n), '^(00000|22P03)$'
FROM (SELECT 0 AS n, arg_sketch_send(v_sketch) AS b FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype
      UNION ALL SELECT 1, ''::bytea
      UNION ALL SELECT 10 + k, substr(arg_sketch_send(v_sketch), 1, cut) FROM pool, unnest(ARRAY[1, 4, 8, 100, 300, 2000])
        WITH ORDINALITY u(cut, k) WHERE class = 'valid' AND typ = 'arg_sketch'::regtype
      UNION ALL SELECT 30 + k, set_byte(b, at, get_byte(b, at) # 1)
        FROM (SELECT arg_sketch_send(v_sketch) AS b FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype) s,
             LATERAL (SELECT k, (('x' || substr(md5('sketch bit' || k), 1, 8))::bit(32)::bigint % length(b))::int AS at
                      FROM generate_series(1, 40) k) p
      UNION ALL SELECT 100 + n, pg_temp.noise('sketch recv ' || n, n * 37) FROM generate_series(1, 10) n
      UNION ALL SELECT 200, arg_sketch_send(v_sketch) || '\x00'::bytea FROM pool WHERE class = 'valid' AND typ = 'arg_sketch'::regtype) s;
INSERT INTO cases (description, queries, allowed)
SELECT format('arg_sketch_out and arg_sketch_send of %s values', class),
       array_agg(format('SELECT length(%s::text) + length(arg_sketch_send(%s))', pg_temp.value_sql(id), pg_temp.value_sql(id)) ORDER BY id),
       CASE WHEN class = 'forged' THEN '^(00000|22...|XX001)$' ELSE '^00000$' END
FROM pool WHERE typ = 'arg_sketch'::regtype AND class IN ('valid', 'unusual', 'forged') GROUP BY class ORDER BY class;
-- Type output of every unusual and forged value.
INSERT INTO cases (description, queries, allowed)
SELECT format('arg_out and arg_send of %s values', class),
       array_agg(format('SELECT length(%s::text) + length(arg_send(%s))', pg_temp.value_sql(id), pg_temp.value_sql(id)) ORDER BY id),
       CASE WHEN class = 'forged' THEN '^(00000|22...|XX001)$' ELSE '^00000$' END
FROM pool WHERE typ = 'arg'::regtype AND class IN ('valid', 'unusual', 'forged') GROUP BY class ORDER BY class;

-- The trigger, misused: wrong argument counts and names, columns of the wrong type or generated,
-- fired AFTER, per statement or on DELETE; and fed NULL, empty, random and truncated meshes.
CREATE TEMP TABLE trig (id serial, mesh bytea, texture bytea, descr arg, title text,
                        gen arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);
CREATE FUNCTION pg_temp.trigger_with(timing text, level text, events text, args text, mesh_sql text) RETURNS text
LANGUAGE plpgsql AS $$
BEGIN
  EXECUTE 'DROP TRIGGER IF EXISTS t ON pg_temp.trig';
  EXECUTE format('CREATE TRIGGER t %s %s ON pg_temp.trig FOR EACH %s EXECUTE FUNCTION arg_index_trigger(%s)',
                 timing, events, level, args);
  EXECUTE format('INSERT INTO pg_temp.trig (mesh) SELECT %s', mesh_sql);
  EXECUTE 'UPDATE pg_temp.trig SET title = ''x''';
  EXECUTE 'DELETE FROM pg_temp.trig';
  RETURN 'done';
END $$;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_index_trigger misused (arguments, columns, timing, level, events)',
       array_agg(format('SELECT pg_temp.trigger_with(%L, %L, %L, %L, %L)', timing, lvl, events, args,
                        '(SELECT bytes FROM pg_temp.valid WHERE name = ''OFF'')') ORDER BY n),
       '^(00000|22023|39P01|42...)$'
FROM (VALUES (1, 'BEFORE', 'ROW', 'INSERT OR UPDATE', ''), (2, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'''),
             (3, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''descr'', ''texture'', '''', ''extra'''),
             (4, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''nope'', ''descr'''),
             (5, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''nope'''),
             (6, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''title'', ''descr'''),
             (7, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''title'''),
             (8, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''gen'''),
             (9, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''descr'', ''title'''),
             (10, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''descr'', '''', ''levels=99'''),
             (11, 'AFTER', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''descr'''),
             (12, 'BEFORE', 'STATEMENT', 'INSERT OR UPDATE', '''mesh'', ''descr'''),
             (13, 'BEFORE', 'ROW', 'DELETE', '''mesh'', ''descr'''),
             (14, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''descr'', ''texture'''),
             (15, 'BEFORE', 'ROW', 'INSERT OR UPDATE', '''mesh'', ''descr'', ''mesh''')) t(n, timing, lvl, events, args);
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_index_trigger fed NULL, empty, random and truncated meshes',
       array_agg(format('SELECT pg_temp.trigger_with(''BEFORE'', ''ROW'', ''INSERT OR UPDATE'', %L, %L)',
                        '''mesh'', ''descr''', pg_temp.value_sql(id)) ORDER BY id),
       '^(00000|22...|54000)$'
FROM pool WHERE typ = 'bytea'::regtype AND class IN ('NULL', 'empty', 'random', 'truncated');

-- The arg_ivf index over every valid and unusual sketch of the pool, searched with each sketch of
-- the pool as the query (a forged one: XX001) at one probe and at every cell; built over a table
-- that holds a forged sketch, and given one on insert (XX001). The functions plan their query
-- with sequential scans off, so that a table this small is searched through its index.
CREATE TEMP TABLE ivf_rows AS
SELECT id, v_sketch AS sk FROM pool WHERE typ = 'arg_sketch'::regtype AND class IN ('valid', 'unusual');
CREATE INDEX ivf_rows_sk ON ivf_rows USING arg_ivf (sk) WITH (lists = 3);
CREATE FUNCTION pg_temp.ivf_search(q arg_sketch, probes text) RETURNS bigint
LANGUAGE plpgsql SET enable_seqscan = off AS $$
BEGIN
  PERFORM set_config('arg.ivf_probes', probes, true);
  RETURN (SELECT count(*) FROM (SELECT id FROM pg_temp.ivf_rows ORDER BY sk <~> q LIMIT 100) s);
END $$;
CREATE FUNCTION pg_temp.ivf_build_with(extra arg_sketch) RETURNS bigint LANGUAGE plpgsql AS $$
BEGIN
  CREATE TEMP TABLE ivf_more AS SELECT sk FROM pg_temp.ivf_rows UNION ALL SELECT extra;
  CREATE INDEX ivf_more_sk ON ivf_more USING arg_ivf (sk) WITH (lists = 2);
  DROP TABLE ivf_more;
  RETURN 1;
END $$;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_ivf searched with every sketch of the pool as the query, 1 and 4096 probes',
       array_agg(format('SELECT pg_temp.ivf_search(%s, %L)', pg_temp.value_sql(id), probes) ORDER BY id, probes),
       '^(00000|XX001)$'
FROM pool, unnest(ARRAY['1', '4096']) probes WHERE typ = 'arg_sketch'::regtype;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_ivf built over a table holding each sketch of the pool',
       array_agg(format('SELECT pg_temp.ivf_build_with(%s)', pg_temp.value_sql(id)) ORDER BY id), '^(00000|XX001)$'
FROM pool WHERE typ = 'arg_sketch'::regtype;
INSERT INTO cases (description, queries, allowed)
SELECT 'arg_ivf given each sketch of the pool on insert',
       array_agg(format('WITH i AS (INSERT INTO pg_temp.ivf_rows VALUES (-1, %s) RETURNING 1) SELECT count(*) FROM i',
                        pg_temp.value_sql(id)) ORDER BY id), '^(00000|XX001)$'
FROM pool WHERE typ = 'arg_sketch'::regtype;

-- The run ------------------------------------------------------------------------------------

SELECT plan((SELECT count(*)::int FROM cases) + 12);

-- Every mesh builds; every texture builds with the textured OBJ.
SELECT is(count(*)::int, 8, 'the cup in OFF, PLY (ASCII and binary), STL (ASCII and binary), OBJ (with and without texture coordinates) and GLB: each builds')
FROM valid WHERE name !~ '^(BMP|TGA)$' AND arg_info(arg_build(bytes)) IS NOT NULL;
SELECT is(count(*)::int, 2, 'a BMP and a TGA texture each build with the textured OBJ')
FROM valid t, valid m WHERE t.name IN ('BMP', 'TGA') AND m.name = 'OBJ (textured)'
  AND arg_info(arg_build(m.bytes, t.bytes)) IS NOT NULL;

-- A colour-mapped RLE TGA with an empty colour map crashed OpenImageIO 2.4's reader (and with
-- it the backend) before the texture check refused colour-mapped TGA (found by fuzzing).
SELECT throws_ok(format('SELECT arg_build(%L::bytea, %L::bytea)', m.bytes,
                        '\x00010914af000020600000000100000208000008'),
                 '22023', NULL, 'a colour-mapped TGA texture is refused with 22023, before the decoder')
FROM valid m WHERE m.name = 'OBJ (textured)';
-- A run-length encoded BMP claiming 24 bits per pixel made OpenImageIO 2.4 throw an exception it
-- cannot pass on, which aborts the process (found by fuzzing); only uncompressed BMP is decoded.
SELECT throws_ok(format('SELECT arg_build(%L::bytea, %L::bytea)', m.bytes,
                        '\x424d4e000000000000000800000028000000030000000200004001001800010000000000000080130b0000130b000000000000000000000064c83c64c87864c8000000c87864c8000000'),
                 '22023', NULL, 'a run-length encoded BMP texture is refused with 22023, before the decoder')
FROM valid m WHERE m.name = 'OBJ (textured)';

SELECT is(array_agg(sig ORDER BY sig), NULL,
          'every function of the extension has valid arguments it accepts (so each hostile argument is the only one)')
FROM funcs WHERE oid NOT IN (SELECT oid FROM baseline);
SELECT is(array_agg(DISTINCT t::text ORDER BY t::text), NULL,
          'every argument type of the extension''s functions has values to try')
FROM funcs, unnest(argtypes) t WHERE pg_temp.column_of(t) IS NULL;

-- One statement per case, so that statement_timeout applies to each.
SET statement_timeout = '2min';
SELECT format('SELECT pg_temp.check_calls(description, queries, allowed, nan_ok) FROM pg_temp.cases WHERE n = %s', n)
FROM cases ORDER BY n \gexec
RESET statement_timeout;

-- After all that: the same backend answers, builds and compares.
SELECT is(pg_backend_pid(), (SELECT pid FROM session), 'the same backend answered every call');
SELECT is(arg_sim(v_arg, v_arg), 0::float8, 'the session still builds and compares: SIM(M, M) = 0')
FROM pool WHERE class = 'valid' AND typ = 'arg'::regtype;
SELECT is(arg_sim(arg_build(bytes), arg_build(bytes)), 0::float8, 'a fresh build still matches itself')
FROM valid WHERE name = 'GLB';
SELECT ok(count(*) = 0, 'nothing was inserted by a failed trigger call') FROM trig;
SELECT ok((SELECT count(*) FROM recv_arg) >= 1 AND (SELECT bool_and(arg_sim(v, v) = 0) FROM recv_arg),
          'what binary COPY let in are valid ARGs');
SELECT ok(pg_stat_get_xact_numscans('pg_temp.ivf_rows_sk'::regclass)
            >= (SELECT 2 * count(*) FROM pool WHERE typ = 'arg_sketch'::regtype AND class <> 'forged'),
          'the arg_ivf searches went through the index');

SELECT * FROM finish();
ROLLBACK;
