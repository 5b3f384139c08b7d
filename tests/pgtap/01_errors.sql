-- Every class of bad input fails with its SQLSTATE, and after each failure the same session
-- still answers a query: no C++ exception and no crash crosses into PostgreSQL.
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SELECT plan(49);

CREATE TEMP TABLE session AS SELECT pg_backend_pid() AS pid;
CREATE TEMP TABLE fixture AS
SELECT arg_generate_model('cup', 0, 16) AS mesh, arg_build(arg_generate_model('cup', 0, 16)) AS descr;
CREATE TEMP TABLE big AS SELECT arg_generate_model('human', 0, 128) AS mesh;

-- After each failure: the session answers, and SIM(M, M) is still 0.
CREATE FUNCTION pg_temp.still_answers(after text) RETURNS text LANGUAGE sql AS $$
  SELECT is((SELECT arg_sim(descr, descr) FROM fixture), 0::float8,
            'after ' || after || ', the session still answers')
$$;

-- The SQLSTATE of a statement, catching a cancel too (pgTAP's throws_ok lets cancels through).
CREATE FUNCTION pg_temp.sqlstate_of(query text) RETURNS text LANGUAGE plpgsql AS $$
BEGIN
  EXECUTE query;
  RETURN '00000';
EXCEPTION WHEN query_canceled OR others THEN
  RETURN SQLSTATE;
END $$;

-- Meshes that cannot be read: 22023, with a message naming the format and the line or offset.
SELECT throws_ok($$ SELECT arg_build(convert_to(E'OFF\n8 12 0\n1 0 0\n-1 0 0\n', 'UTF8')) $$,
                 '22023', NULL, 'a truncated OFF file is rejected (22023)');
SELECT pg_temp.still_answers('a truncated OFF file');
SELECT throws_ok($$ SELECT arg_build(substr(mesh, 1, octet_length(mesh) / 2)) FROM fixture $$,
                 '22023', NULL, 'a generated OFF file cut in half is rejected (22023)');
SELECT pg_temp.still_answers('half a file');
SELECT throws_ok($$ SELECT arg_build('\x00ff13deadbeef0102030405060708090a0b0c0d0e0f'::bytea) $$,
                 '22023', NULL, 'binary garbage is rejected (22023)');
SELECT pg_temp.still_answers('binary garbage');
SELECT throws_ok($$ SELECT arg_build(convert_to(E'ply\nformat binary_little_endian 1.0\n'
                                                'element vertex 3\nproperty float x\nproperty float y\n'
                                                'property float z\nelement face 1\n'
                                                'property list uchar int vertex_indices\nend_header\n',
                                                'UTF8') || '\x0000803f00000000'::bytea) $$,
                 '22023', NULL, 'a binary PLY with a truncated body is rejected (22023)');
SELECT pg_temp.still_answers('a truncated PLY');
SELECT throws_ok($$ SELECT arg_build(convert_to(E'OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n', 'UTF8')) $$,
                 '22023', NULL, 'a NaN vertex coordinate is rejected (22023)');
SELECT pg_temp.still_answers('a NaN vertex');
SELECT throws_ok($$ SELECT arg_build(convert_to(E'OFF\n3 1 0\n0 0 0\n1 1e39 0\n0 1 0\n3 0 1 2\n', 'UTF8')) $$,
                 '22023', NULL, 'an infinite vertex coordinate is rejected (22023)');
SELECT pg_temp.still_answers('an infinite vertex');
SELECT throws_ok($$ SELECT arg_build(convert_to(E'OFF\n0 0 0\n', 'UTF8')) $$,
                 '22023', NULL, 'an empty mesh is rejected (22023)');
SELECT pg_temp.still_answers('an empty mesh');
SELECT throws_ok($$ SELECT arg_build(''::bytea) $$,
                 '22023', NULL, 'zero bytes are rejected (22023)');
SELECT pg_temp.still_answers('zero bytes');
SELECT throws_ok($$ SELECT arg_build(convert_to(E'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n', 'UTF8')) $$,
                 '22023', NULL, 'a face naming a vertex that does not exist is rejected (22023)');
SELECT pg_temp.still_answers('a face out of range');

-- Bad options and arguments: 22023.
SELECT throws_ok($$ SELECT arg_build(mesh, 'no_such_option=1') FROM fixture $$,
                 '22023', NULL, 'an unknown build option is rejected (22023)');
SELECT throws_ok($$ SELECT * FROM fixture, arg_part_match(descr, 9, 0, descr) $$,
                 '22023', NULL, 'a part match at a level the query does not have is rejected (22023)');
SELECT throws_ok($$ SELECT arg_generate_model('teapot', 0) $$,
                 '22023', NULL, 'an unknown model class is rejected (22023)');
SELECT throws_ok($$ SELECT arg_generate_model('cup', 0, 4096) $$,
                 '22023', NULL, 'a generator resolution over 128 is rejected (22023)');
SELECT pg_temp.still_answers('bad arguments');

-- Oversized input: 54000, before the mesh is read.
SET arg.max_input_size = '64kB';
SELECT throws_ok($$ SELECT arg_build(mesh) FROM big $$,
                 '54000', NULL, 'a mesh over arg.max_input_size is rejected (54000)');
RESET arg.max_input_size;
SELECT pg_temp.still_answers('an oversized mesh');
SET arg.max_triangles = 1000;
SELECT throws_ok($$ SELECT arg_build(mesh) FROM big $$,
                 '54000', NULL, 'a mesh over arg.max_triangles is rejected (54000)');
RESET arg.max_triangles;
SELECT pg_temp.still_answers('too many triangles');

-- Over the build's memory cap: 54000 from the estimate, before the build allocates.
SET arg.max_build_memory = '16MB';
SELECT throws_like($$ SELECT arg_build(mesh) FROM big $$,
                   '%needs an estimated % MB, more than the build memory cap of 16 MB (arg.max_build_memory)',
                   'a mesh whose build needs more than arg.max_build_memory is refused, naming both');
SELECT is(pg_temp.sqlstate_of($$ SELECT arg_build(mesh) FROM big $$), '54000',
          'a build over arg.max_build_memory fails with 54000');
RESET arg.max_build_memory;
SELECT pg_temp.still_answers('a build over the memory cap');
SELECT lives_ok($$ SELECT arg_build(mesh) FROM big $$, 'under the default cap the same mesh builds');

-- Bad arg values: 22P02 for text input, as strict as binary input.
SELECT throws_ok($$ SELECT ('arg1:' || overlay(t PLACING CASE WHEN substr(t, 1001, 1) = 'B' THEN 'C' ELSE 'B' END
                                                FROM 1001 FOR 1))::arg
                    FROM (SELECT substr(descr::text, 6) AS t FROM fixture) s $$,
                 '22P02', NULL, 'arg text with one character changed is rejected (22P02)');
SELECT pg_temp.still_answers('corrupted arg text');
SELECT throws_ok($$ SELECT left(descr::text, 400)::arg FROM fixture $$,
                 '22P02', NULL, 'truncated arg text is rejected (22P02)');
SELECT pg_temp.still_answers('truncated arg text');
SELECT throws_ok($$ SELECT ('arg2:' || substr(descr::text, 6))::arg FROM fixture $$,
                 '22P02', NULL, 'arg text with another version tag is rejected (22P02)');
SELECT pg_temp.still_answers('a wrong version tag');
SELECT throws_ok($$ SELECT 'arg1:QVJHUgEAKAE='::arg $$,
                 '22P02', NULL, 'a bare header is rejected (22P02)');
SELECT throws_ok($$ SELECT 'not an arg'::arg $$,
                 '22P02', NULL, 'text that is not an ARG is rejected (22P02)');
SELECT throws_ok($$ SELECT 'arg1:@@@@'::arg $$,
                 '22P02', NULL, 'arg text that is not base64 is rejected (22P02)');
SELECT pg_temp.still_answers('other bad arg text');
SELECT throws_ok($$ SELECT 'no_such_preset'::arg_weights $$,
                 '22P02', NULL, 'unknown weights are rejected (22P02)');
SELECT throws_ok($$ SELECT 'lambda_2=nan'::arg_weights $$,
                 '22P02', NULL, 'a NaN weight is rejected (22P02)');
SELECT pg_temp.still_answers('bad weights');

-- Long builds stop when the statement times out: 57014, and the session goes on.
SET statement_timeout = '20ms';
SELECT is(pg_temp.sqlstate_of('SELECT arg_build(mesh) FROM big'), '57014',
          'a build that runs past statement_timeout is cancelled (57014)');
RESET statement_timeout;
SELECT pg_temp.still_answers('a cancelled build');

-- A sketch carries a digest: any changed bit of its bytes is refused (22P02) on input, while a
-- version-1 sketch (arg 0.2.0's, no digest) still reads as the same sketch.
CREATE FUNCTION pg_temp.sketch_text(b bytea) RETURNS text LANGUAGE sql AS $$
  SELECT 'sketch1:' || translate(encode(b, 'base64'), E'\n', '') $$;
CREATE FUNCTION pg_temp.accepted_flips(b bytea, n int) RETURNS int LANGUAGE plpgsql AS $$
DECLARE
  at int;
  accepted int := 0;
BEGIN
  FOR k IN 1..n LOOP
    at := (k * 7919) % length(b);
    BEGIN
      PERFORM pg_temp.sketch_text(set_byte(b, at, get_byte(b, at) # (1 << (k % 8))))::arg_sketch;
      accepted := accepted + 1;
    EXCEPTION WHEN invalid_text_representation THEN
    END;
  END LOOP;
  RETURN accepted;
END $$;
SELECT is(pg_temp.accepted_flips((SELECT arg_sketch_send(arg_sketch(descr)) FROM fixture), 400), 0,
          'none of 400 sketches with one bit changed is accepted');
SELECT is((SELECT arg_sketch_dist(pg_temp.sketch_text(substr(b, 1, 4) || '\x01'::bytea ||
                                                      substr(b, 6, 3) || substr(b, 17))::arg_sketch,
                                  arg_sketch(descr))
           FROM fixture, LATERAL (SELECT arg_sketch_send(arg_sketch(descr)) AS b) s),
          0::float8, 'a version-1 sketch (no digest) still reads, as the same sketch');

SELECT is(pg_backend_pid(), (SELECT pid FROM session), 'the same backend answered every query');

SELECT * FROM finish();
ROLLBACK;
