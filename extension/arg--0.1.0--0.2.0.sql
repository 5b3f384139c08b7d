-- arg 0.1.0 to 0.2.0: comparing refuses ARGs of other builder versions or options, and
-- arg_rebuild_needed finds the values to build again. Values stored by 0.1.0 (binary format 1,
-- builder 1.0) still read and compare with each other; docs/REFERENCE.md "Upgrading" says how
-- to rebuild them. arg_global of this library gives other values than 0.1.0's (92 numbers that
-- see the panorama and the spectrum, not 98 level sums): REINDEX indexes on it and renew stored
-- descriptor columns once it is installed (the same section).

-- complain if script is sourced in psql, rather than via ALTER EXTENSION
\echo Use "ALTER EXTENSION arg UPDATE TO '0.2.0'" to load this file. \quit

COMMENT ON TYPE arg_weights IS
  'weights of matching and SIM: a preset (arg, mrg, graph, shape, colour) and/or key=value pairs '
  '(alpha_l beta_l gamma_l delta_l eps_l alpha_s beta_s lambda_1..lambda_4 graph panorama spectrum '
  'graph_on_proxy norm tung groups, or the readable names loss_area loss_length loss_radius loss_theta '
  'loss_phi area length volume cords curvature colour)';

COMMENT ON FUNCTION arg_build(bytea, text) IS
  'ARG of a mesh (OFF, OBJ, PLY, STL or GLB, detected); options like ''levels=5 mu=geodesic base_points=128 surface=auto''';

COMMENT ON FUNCTION arg_sim(arg, arg, arg_weights) IS
  'SIM(a, b) in [0, 1], 0 for the same shape, symmetric; error 22023 for ARGs of other builder versions or options';

COMMENT ON FUNCTION arg_global_vector(arg) IS
  'the 92-value global descriptor of an ARG (the panorama''s lowest frequencies, eigenvalues and level sums), for candidate search';

COMMENT ON FUNCTION arg_info(arg) IS
  'levels, nodes per level, genus estimate, triangles, build options, builder version and format version of an ARG';

-- STABLE, not IMMUTABLE: the same value needs a rebuild or not depending on the library that is
-- installed, so it must not feed an index or a generated column.
CREATE FUNCTION arg_rebuild_needed(arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_rebuild_needed' LANGUAGE C STABLE STRICT PARALLEL SAFE COST 1600;

COMMENT ON FUNCTION arg_rebuild_needed(arg) IS
  'true when this library would build the ARG differently: an older binary format, or a builder of another major or minor version';
