-- arg 0.3.0: an arg_ivf index on an arg column itself (one CREATE INDEX, no sketch column);
-- ORDER BY descr <~> q LIMIT k takes it and returns rows in exact SIM order. arg_sim_terms
-- explains a SIM term by term. The `arg` preset weighs cords 0.5 and curvature 12 (0.2.0: 1
-- and 3), so SIM values differ from 0.2.0's; the new `part` preset keeps 0.2.0's, and
-- arg_part_match uses it by default. An arg_weights value stored before keeps the numbers it
-- was given.

\echo Use "ALTER EXTENSION arg UPDATE TO '0.3.0'" to load this file. \quit

-- The library (arg.so) must be at least as new as this script: an older one lacks what the
-- script creates and cannot read what it may write. A session that loaded the library before it
-- was replaced still runs the old one, hence the hint to reconnect.
DO $check$
DECLARE
  library text := substring(@extschema@.arg_version() FROM '^arg ([0-9]+[.][0-9]+[.][0-9]+)');
BEGIN
  IF library IS NULL OR string_to_array(library, '.')::int[] < string_to_array('0.3.0', '.')::int[] THEN
    RAISE EXCEPTION 'arg version mismatch: the library is %, this SQL script is 0.3.0',
                    coalesce(library, @extschema@.arg_version())
      USING ERRCODE = 'feature_not_supported',
            HINT = 'Install arg.so and the SQL scripts from one release, then reconnect.';
  END IF;
END
$check$;

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

-- Builder 1.7 sums mu over 96 base points by default (128 before).
COMMENT ON FUNCTION arg_build(bytea, text) IS
  'ARG of a mesh (OFF, OBJ, PLY, STL or GLB, detected); options like ''levels=5 mu=geodesic base_points=96 surface=auto''';

COMMENT ON FUNCTION arg_index_check(regclass) IS
  'checks an arg_ivf index: every page and entry, and every live row of its table indexed once under its value''s sketch';

-- arg_knn resolves nothing through a schema other roles may write into: its search_path is
-- pg_catalog then pg_temp, and every object of arg and cube it uses is named with its schema (a
-- function or operator someone planted in public, a closer match than the built-in one, ran
-- inside arg_knn as the caller). The plain query through an arg_ivf index on the arg column now
-- does what arg_knn did with a sketch column.
CREATE OR REPLACE FUNCTION arg_knn(tbl anyelement, col name, query arg, k int DEFAULT 10,
                        candidates int DEFAULT NULL, filter jsonb DEFAULT NULL,
                        descriptor name DEFAULT NULL, sketch name DEFAULT NULL,
                        shortlist int DEFAULT NULL)
  RETURNS TABLE (obj anyelement, sim float8)
  LANGUAGE plpgsql STABLE
  SET search_path = pg_catalog, pg_temp
  ROWS 10
AS $$
DECLARE
  relid oid;
  kind "char";
  children bool;
  conditions text := '';
  nearest text;
  sq @extschema@.arg_sketch;
  cube_ns oid;
  cube_schema name;
  stages text;
  seqscan text := current_setting('enable_seqscan');
  item record;
BEGIN
  SELECT c.oid, c.relkind, c.relhassubclass INTO relid, kind, children
  FROM pg_type t JOIN pg_class c ON c.oid = t.typrelid
  WHERE t.oid = pg_typeof(tbl) AND c.relkind IN ('r', 'p', 'v', 'm', 'f');
  IF relid IS NULL THEN
    RAISE EXCEPTION 'arg_knn: tbl must be NULL cast to a table''s row type, as in NULL::objects'
      USING ERRCODE = 'invalid_parameter_value';
  END IF;
  IF k IS NULL OR k < 1 THEN
    RAISE EXCEPTION 'arg_knn: k must be at least 1' USING ERRCODE = 'invalid_parameter_value';
  END IF;
  IF shortlist < 1 THEN
    RAISE EXCEPTION 'arg_knn: shortlist must be at least 1'
      USING ERRCODE = 'invalid_parameter_value';
  END IF;
  IF shortlist IS NOT NULL AND sketch IS NULL THEN
    RAISE EXCEPTION 'arg_knn: a shortlist needs a sketch column (sketch => ...)'
      USING ERRCODE = 'invalid_parameter_value';
  END IF;
  IF query IS NULL OR col IS NULL THEN
    RETURN;
  END IF;
  -- cube's schema (the extension arg requires), to name its operator and type.
  SELECT e.extnamespace, n.nspname INTO cube_ns, cube_schema
  FROM pg_extension e JOIN pg_namespace n ON n.oid = e.extnamespace WHERE e.extname = 'cube';
  IF NOT EXISTS (SELECT FROM pg_attribute a WHERE a.attrelid = relid AND a.attname = col
                   AND a.attnum > 0 AND NOT a.attisdropped AND a.atttypid = pg_typeof(query)) THEN
    RAISE EXCEPTION 'arg_knn: % has no column % of type arg', relid::regclass, quote_ident(col)
      USING ERRCODE = 'undefined_column';
  END IF;
  IF descriptor IS NOT NULL AND NOT EXISTS (
       SELECT FROM pg_attribute a WHERE a.attrelid = relid AND a.attname = descriptor
         AND a.attnum > 0 AND NOT a.attisdropped
         AND a.atttypid = (SELECT t.oid FROM pg_type t WHERE t.typname = 'cube' AND t.typnamespace = cube_ns)) THEN
    RAISE EXCEPTION 'arg_knn: % has no column % of type cube', relid::regclass, quote_ident(descriptor)
      USING ERRCODE = 'undefined_column';
  END IF;
  IF sketch IS NOT NULL THEN
    sq := @extschema@.arg_sketch(query);
    IF NOT EXISTS (
         SELECT FROM pg_attribute a WHERE a.attrelid = relid AND a.attname = sketch
           AND a.attnum > 0 AND NOT a.attisdropped AND a.atttypid = pg_typeof(sq)) THEN
      RAISE EXCEPTION 'arg_knn: % has no column % of type arg_sketch', relid::regclass,
        quote_ident(sketch) USING ERRCODE = 'undefined_column';
    END IF;
  END IF;
  IF filter IS NOT NULL THEN
    IF jsonb_typeof(filter) <> 'object' THEN
      RAISE EXCEPTION 'arg_knn: filter must be a jsonb object of column: value pairs'
        USING ERRCODE = 'invalid_parameter_value';
    END IF;
    FOR item IN SELECT key, value FROM jsonb_each(filter) ORDER BY key LOOP
      conditions := conditions || CASE
        WHEN jsonb_typeof(item.value) = 'null' THEN format(' AND t.%I IS NULL', item.key)
        ELSE format(' AND t.%I = %L', item.key, item.value #>> '{}') END;
    END LOOP;
  END IF;
  -- A sketch column with an arg_ivf index (on the column itself, not partial) gives the
  -- shortlist straight from the index, when no filter would remove most of what the index
  -- returns and no descriptor is asked for. Should the probed cells hold fewer than k rows,
  -- every other row is ranked too (a one-time test: not even scanned otherwise), told apart
  -- by row address: so only for a table without inheritance children, or a partitioned one
  -- whose partitions are all tables (a foreign partition's rows have no address).
  IF sketch IS NOT NULL AND filter IS NULL AND descriptor IS NULL
     AND ((kind IN ('r', 'm') AND NOT children)
          OR (kind = 'p' AND NOT EXISTS (
                SELECT FROM pg_partition_tree(relid) p JOIN pg_class c ON c.oid = p.relid
                WHERE p.isleaf AND c.relkind NOT IN ('r', 'm'))))
     AND EXISTS (
       SELECT FROM pg_index i JOIN pg_class ic ON ic.oid = i.indexrelid
         JOIN pg_am am ON am.oid = ic.relam AND am.amname = 'arg_ivf'
         JOIN pg_attribute a ON a.attrelid = relid AND a.attname = sketch
       WHERE i.indrelid = relid AND i.indisvalid AND i.indnatts = 1 AND i.indkey[0] = a.attnum
         AND i.indpred IS NULL AND i.indexprs IS NULL) THEN
    PERFORM set_config('enable_seqscan', 'off', true);
    RETURN QUERY EXECUTE format(
      'WITH idx AS MATERIALIZED (
         SELECT t.tableoid AS rel, t.ctid AS tid, ROW(t.*)::%2$s AS r FROM %2$s t
         WHERE t.%1$I IS NOT NULL ORDER BY t.%3$I OPERATOR(@extschema@.<~>) $2 LIMIT $3),
       cand AS (
         SELECT idx.r FROM idx
         UNION ALL
         SELECT ROW(t.*)::%2$s FROM %2$s t
         WHERE (SELECT count(*) FROM idx) < $4 AND t.%1$I IS NOT NULL
           AND (t.tableoid, t.ctid) NOT IN (SELECT idx.rel, idx.tid FROM idx))
       SELECT c.r, (c.r).%1$I OPERATOR(@extschema@.<~>) $1 AS sim FROM cand c
       ORDER BY sim, (c.r).%1$I LIMIT $4',
      col, relid::regclass, sketch)
    USING query, sq, greatest(coalesce(shortlist, greatest(20 * k, 200)), k), k;
    PERFORM set_config('enable_seqscan', seqscan, true);
    RETURN;
  END IF;
  IF descriptor IS NULL THEN
    nearest := format('@extschema@.arg_global(t.%I)', col);
    PERFORM set_config('enable_seqscan', 'off', true);
  ELSE
    nearest := format('t.%I', descriptor);
  END IF;
  -- (Only for a relation without inheritance children: their row addresses repeat the parent's.)
  IF kind IN ('r', 'm') AND NOT children THEN
    -- The first stage sorts row addresses, not rows: a sort of thousands of whole rows outgrows
    -- work_mem and spills every row of the table to disk (measured: 81 MB and 150 ms at 100,000
    -- rows); the candidates are then fetched by address (same snapshot, same statement).
    stages := format('SELECT t.* FROM %1$s t WHERE t.ctid = ANY (ARRAY(
                        SELECT t.ctid FROM %1$s t WHERE t.%2$I IS NOT NULL%3$s
                        ORDER BY %4$s OPERATOR(%5$I.<#>) @extschema@.arg_global($1) LIMIT $3))',
                     relid::regclass, col, conditions, nearest, cube_schema);
  ELSE
    stages := format('SELECT t.* FROM %s t WHERE t.%I IS NOT NULL%s
                      ORDER BY %s OPERATOR(%I.<#>) @extschema@.arg_global($1) LIMIT $3',
                     relid::regclass, col, conditions, nearest, cube_schema);
  END IF;
  IF sketch IS NOT NULL THEN
    stages := format('SELECT t.* FROM (%s) t ORDER BY @extschema@.arg_sketch_distance(t.%I, $5) LIMIT $6',
                     stages, sketch);
  END IF;
  -- The row value is formed only for the candidates, after the LIMIT: a whole-row reference
  -- in the scan itself would detoast every ARG the first stages look at.
  RETURN QUERY EXECUTE format(
    'SELECT c.r, (c.r).%1$I OPERATOR(@extschema@.<~>) $1 AS sim
     FROM (SELECT ROW(s.*)::%2$s AS r FROM (%3$s) s) c
     ORDER BY sim, (c.r).%1$I LIMIT $4',
    col, relid::regclass, stages)
  USING query, NULL::text,
        greatest(coalesce(candidates, CASE WHEN sketch IS NULL THEN greatest(100 * k, 1000)
                                           ELSE greatest(300 * k, 3000) END), k),
        k, sq, greatest(coalesce(shortlist, greatest(20 * k, 200)), k);
  PERFORM set_config('enable_seqscan', seqscan, true);
END
$$;

COMMENT ON FUNCTION arg_knn(anyelement, name, arg, int, int, jsonb, name, name, int) IS
  'search in stages: the candidates nearest by arg_global (GiST index, or a stored descriptor column) by <#>, then with a stored arg_sketch column the shortlist nearest by arg_sketch_distance (straight from an arg_ivf index on it, without filter or descriptor), ranked exactly by <~>; returns (row, sim), best first';

-- SIM explained: the graph, panorama and spectrum terms with the weights they got, their
-- distances and their shares of SIM (which add up to arg_sim exactly, in this order), then the
-- graph's features (the weight of each, and its part of 1 - the graph's SIM).
CREATE FUNCTION arg_sim_terms(a arg, b arg, weights arg_weights DEFAULT 'arg')
  RETURNS TABLE (term text, weight float8, value float8, contribution float8)
  AS 'MODULE_PATHNAME', 'arg_sim_terms' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 600 ROWS 9;

COMMENT ON FUNCTION arg_sim_terms(arg, arg, arg_weights) IS
  'SIM(a, b, weights) term by term: graph, panorama, spectrum (weight, distance, share of SIM; the shares add up to arg_sim), then the graph''s features';

-- A default of type arg_weights is stored as the value the preset's name read as when the
-- function was created, by the library of that time: a database made by 0.1.0 or 0.2.0 holds
-- their weights (0.1.0's the graph alone) behind every DEFAULT 'arg'. Each such function is
-- created again here, so its default is read by this library and arg_sim(a, b) = a <~> b.
-- Whole models rank best with the `arg` preset's curvature and cords, a part against parts with
-- the `part` preset's (docs/BENCHMARKS.md, "Part matching").
COMMENT ON TYPE arg_weights IS
  'weights of matching and SIM: a preset (arg, part, mrg, graph, shape, colour) and/or key=value pairs '
  '(alpha_l beta_l gamma_l delta_l eps_l alpha_s beta_s lambda_1..lambda_4 graph panorama spectrum '
  'graph_on_proxy level_ratio norm tung groups, or the readable names loss_area loss_length loss_radius loss_theta '
  'loss_phi area length volume cords curvature colour)';

CREATE OR REPLACE FUNCTION arg_sim(a arg, b arg, weights arg_weights DEFAULT 'arg') RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_sim' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 2000;

CREATE OR REPLACE FUNCTION arg_matches(a arg, b arg, weights arg_weights DEFAULT 'arg')
  RETURNS TABLE (level int, a_node int, b_node int, match_group int, loss float8, sim float8)
  AS 'MODULE_PATHNAME', 'arg_matches' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 600 ROWS 40;

CREATE OR REPLACE FUNCTION arg_sketch_distance(a arg_sketch, b arg_sketch,
                                               weights arg_weights DEFAULT 'arg')
  RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_sketch_distance' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 20;

CREATE OR REPLACE FUNCTION arg_part_match(query arg, level int, node int, candidate arg,
                                          weights arg_weights DEFAULT 'part')
  RETURNS TABLE (candidate_level int, candidate_node int, score float8)
  AS 'MODULE_PATHNAME', 'arg_part_match' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 1500 ROWS 5;
