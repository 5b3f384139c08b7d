-- arg 0.3.0: an arg_ivf index on an arg column itself (one CREATE INDEX, no sketch column);
-- ORDER BY descr <~> q LIMIT k takes it and returns rows in exact SIM order.

\echo Use "ALTER EXTENSION arg UPDATE TO '0.3.0'" to load this file. \quit

-- The index keeps each value's sketch; a search ranks the sketches of the cells nearest the
-- query, then the nearest arg.ivf_candidates of them by SIM, read from the table.
CREATE OPERATOR CLASS arg_ops DEFAULT FOR TYPE arg USING arg_ivf AS
  OPERATOR 1 <~> (arg, arg) FOR ORDER BY float_ops;

COMMENT ON OPERATOR CLASS arg_ops USING arg_ivf IS
  'orders arg values by <~> (SIM): candidates by sketch, re-ranked by SIM';

-- The integrity of an arg_ivf index: every page, link and entry read strictly, and every live
-- row of its table held exactly once, under the sketch of the value it holds now (XX002 names
-- the first fault). Needs SELECT on the table.
CREATE FUNCTION arg_index_check(index regclass,
                                OUT list_pages bigint, OUT entries bigint, OUT table_rows bigint)
  AS 'MODULE_PATHNAME', 'arg_index_check' LANGUAGE C STRICT PARALLEL RESTRICTED;

COMMENT ON FUNCTION arg_index_check(regclass) IS
  'checks an arg_ivf index: every page and entry, and every live row of its table indexed once under its value''s sketch';
