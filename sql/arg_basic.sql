-- arg_basic: the extension loads, builds an ARG from a mesh, and compares shapes.

CREATE EXTENSION arg;

-- The type: a variable-length value, stored out of line (uncompressed) when large.
SELECT typname, typlen, typstorage FROM pg_type WHERE typname = 'arg';

SELECT arg_version();

-- Meshes are bytes in any of the formats arg_build detects (OFF, OBJ, PLY, STL, GLB).
-- Three small closed meshes written by hand in OFF: a regular octahedron, the same octahedron
-- stretched three times along z, and a tetrahedron. The ARG is a generated column.
CREATE TABLE shapes (
  name  text PRIMARY KEY,
  mesh  bytea NOT NULL,
  descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED
);

INSERT INTO shapes (name, mesh) VALUES
('octahedron', convert_to('OFF
6 8 0
 1  0  0
-1  0  0
 0  1  0
 0 -1  0
 0  0  1
 0  0 -1
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
', 'UTF8')),
('tall octahedron', convert_to('OFF
6 8 0
 1  0  0
-1  0  0
 0  1  0
 0 -1  0
 0  0  3
 0  0 -3
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
', 'UTF8')),
('tetrahedron', convert_to('OFF
4 4 0
 1  1  1
 1 -1 -1
-1  1 -1
-1 -1  1
3 0 1 2
3 0 3 1
3 0 2 3
3 1 3 2
', 'UTF8'));

SELECT name, descr IS NOT NULL AS built FROM shapes ORDER BY name;

-- The text form is "arg1:" and base64 of the binary form; it reads back to the same value.
SELECT name, left(descr::text, 5) AS tag,
       arg_send(arg_in(arg_out(descr))) = arg_send(descr) AS round_trip
FROM shapes ORDER BY name;

-- SIM is 0 for a shape and itself, lies in [0, 1], is symmetric, and tells different shapes apart.
SELECT name, arg_sim(descr, descr) AS self_sim, descr <~> descr AS self_distance
FROM shapes ORDER BY name;

SELECT a.name AS a, b.name AS b,
       arg_sim(a.descr, b.descr) > 0 AS different,
       arg_sim(a.descr, b.descr) <= 1 AS at_most_1,
       arg_sim(a.descr, b.descr) = arg_sim(b.descr, a.descr) AS symmetric,
       arg_sim(a.descr, b.descr) = a.descr <~> b.descr AS operator_agrees
FROM shapes a, shapes b WHERE a.name < b.name ORDER BY a.name, b.name;

-- Other weights: a preset name, or key=value pairs (an arg_weights value).
SELECT arg_sim(descr, descr, 'mrg') AS mrg, arg_sim(descr, descr, 'shape lambda_1=0.1') AS custom
FROM shapes WHERE name = 'octahedron';

-- The closest shape to the octahedron is itself.
SELECT name FROM shapes
ORDER BY descr <~> (SELECT descr FROM shapes WHERE name = 'octahedron'), name LIMIT 1;

-- Bad input gives a clear error and the session goes on.
SELECT arg_build(convert_to('OFF
6 8 0
 1  0  0
', 'UTF8'));
SELECT arg_build('\x00ff13'::bytea);
SELECT 'not an arg'::arg;
SELECT arg_sim(descr, descr, 'no_such_preset') FROM shapes WHERE name = 'octahedron';
SELECT arg_build(mesh, 'levels=99') FROM shapes WHERE name = 'octahedron';
SELECT count(*) AS shapes_still_there FROM shapes;

DROP TABLE shapes;
DROP EXTENSION arg;
