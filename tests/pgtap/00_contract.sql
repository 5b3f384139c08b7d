-- The SQL contract of the extension: objects, their markings, and the SQLSTATE of each failure.
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg;
SELECT plan(46);

SELECT has_extension('arg', 'the arg extension is installed');
SELECT has_type('arg', 'type arg exists');
SELECT has_operator('arg', '<~>', 'arg', 'double precision', 'operator arg <~> arg exists');

-- Every function of the SQL surface, with its signature and return type.
SELECT has_function('arg_in', ARRAY['cstring']);
SELECT has_function('arg_out', ARRAY['arg']);
SELECT has_function('arg_recv', ARRAY['internal']);
SELECT has_function('arg_send', ARRAY['arg']);
SELECT has_function('arg_build', ARRAY['bytea', 'text']);
SELECT has_function('arg_build', ARRAY['bytea', 'bytea', 'text']);
SELECT has_function('arg_sim', ARRAY['arg', 'arg', 'text']);
SELECT has_function('arg_distance', ARRAY['arg', 'arg']);
SELECT has_function('arg_version', '{}'::name[]);
SELECT function_returns('arg_build', ARRAY['bytea', 'text'], 'arg');
SELECT function_returns('arg_sim', ARRAY['arg', 'arg', 'text'], 'double precision');

-- Pure functions are IMMUTABLE STRICT PARALLEL SAFE, so they work in generated columns,
-- indexes and parallel plans.
CREATE TEMP TABLE pure_functions (sig regprocedure);
INSERT INTO pure_functions VALUES
  ('arg_in(cstring)'), ('arg_out(arg)'), ('arg_recv(internal)'), ('arg_send(arg)'),
  ('arg_build(bytea,text)'), ('arg_build(bytea,bytea,text)'), ('arg_sim(arg,arg,text)'),
  ('arg_distance(arg,arg)');
SELECT is(p.provolatile, 'i', f.sig::text || ' is IMMUTABLE')
FROM pure_functions f JOIN pg_proc p ON p.oid = f.sig ORDER BY f.sig::text;
SELECT ok(p.proisstrict, f.sig::text || ' is STRICT')
FROM pure_functions f JOIN pg_proc p ON p.oid = f.sig ORDER BY f.sig::text;
SELECT is(p.proparallel, 's', f.sig::text || ' is PARALLEL SAFE')
FROM pure_functions f JOIN pg_proc p ON p.oid = f.sig ORDER BY f.sig::text;

-- Building and comparing work on a closed mesh.
CREATE TEMP TABLE octahedron AS
SELECT convert_to(E'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n'
                  '3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n',
                  'UTF8') AS mesh;
SELECT lives_ok($$ SELECT arg_build(mesh) FROM octahedron $$, 'an octahedron builds');
SELECT is(arg_sim(arg_build(mesh), arg_build(mesh)), 0::float8, 'self-similarity is zero')
FROM octahedron;

-- Each kind of failure has its SQLSTATE.
SELECT throws_ok($$ SELECT arg_build(convert_to(E'OFF\n6 8 0\n1 0 0\n', 'UTF8')) $$,
                 '22023', NULL, 'a truncated OFF file is rejected (22023)');
SELECT throws_ok($$ SELECT arg_build('\x00ff13deadbeef'::bytea) $$,
                 '22023', NULL, 'garbage bytes are rejected (22023)');
SELECT throws_ok($$ SELECT arg_build(mesh, 'no_such_option=1') FROM octahedron $$,
                 '22023', NULL, 'an unknown build option is rejected (22023)');
SELECT throws_ok($$ SELECT 'not an arg'::arg $$,
                 '22P02', NULL, 'text that is not an ARG is rejected (22P02)');
SELECT throws_ok($$ SELECT 'arg1:QUJD'::arg $$,
                 '22P02', NULL, 'base64 that is not an ARG is rejected (22P02)');
SELECT throws_ok($$ SELECT arg_sim(a, a, 'no_such_preset') FROM (SELECT arg_build(mesh) AS a FROM octahedron) s $$,
                 '22023', NULL, 'unknown weights are rejected (22023)');

SELECT * FROM finish();
ROLLBACK;
