-- arg 0.1.0: the arg type, building ARGs from meshes, and comparing them.

-- complain if script is sourced in psql, rather than via CREATE EXTENSION
\echo Use "CREATE EXTENSION arg" to load this file. \quit

-- The type -----------------------------------------------------------------------------------

CREATE TYPE arg;

CREATE FUNCTION arg_in(cstring) RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_in' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_out(arg) RETURNS cstring
  AS 'MODULE_PATHNAME', 'arg_out' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_recv(internal) RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_recv' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_send(arg) RETURNS bytea
  AS 'MODULE_PATHNAME', 'arg_send' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE TYPE arg (
  INPUT = arg_in,
  OUTPUT = arg_out,
  RECEIVE = arg_recv,
  SEND = arg_send,
  INTERNALLENGTH = VARIABLE,
  STORAGE = extended
);

COMMENT ON TYPE arg IS
  'Augmented Reeb Graph of a 3D mesh (text form: arg1: followed by base64 of the binary form)';

-- Building -----------------------------------------------------------------------------------

CREATE FUNCTION arg_build(mesh bytea, options text DEFAULT '') RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_build_mesh' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 100000;

COMMENT ON FUNCTION arg_build(bytea, text) IS
  'ARG of a mesh (OFF, OBJ, PLY, STL or GLB, detected); options like ''levels=5 mu=geodesic base_points=128''';

CREATE FUNCTION arg_build(mesh bytea, texture bytea, options text DEFAULT '') RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_build_textured' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 100000;

COMMENT ON FUNCTION arg_build(bytea, bytea, text) IS
  'ARG of a mesh whose texture image (PNG, JPEG, ...) is kept outside it, as OBJ does';

-- Comparing ----------------------------------------------------------------------------------

CREATE FUNCTION arg_sim(a arg, b arg, weights text DEFAULT 'arg') RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_sim' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1000;

COMMENT ON FUNCTION arg_sim(arg, arg, text) IS
  'SIM(a, b) in [0, 1], 0 for the same shape; weights: a preset (arg, mrg, shape, colour) and/or key=value pairs';

CREATE FUNCTION arg_distance(a arg, b arg) RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_distance' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1000;

COMMENT ON FUNCTION arg_distance(arg, arg) IS 'arg_sim(a, b) with the default weights; the <~> operator';

CREATE OPERATOR <~> (
  LEFTARG = arg,
  RIGHTARG = arg,
  FUNCTION = arg_distance,
  COMMUTATOR = <~>
);

COMMENT ON OPERATOR <~> (arg, arg) IS 'shape dissimilarity (SIM with default weights), for ORDER BY';

-- About --------------------------------------------------------------------------------------

CREATE FUNCTION arg_version() RETURNS text
  AS 'MODULE_PATHNAME', 'arg_version' LANGUAGE C STABLE PARALLEL SAFE;

COMMENT ON FUNCTION arg_version() IS 'version of the arg extension and of the binary format it writes';
