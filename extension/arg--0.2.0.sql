-- arg 0.2.0: Augmented Reeb Graphs of 3D meshes, built, compared and inspected in SQL.
--
-- A database at 0.1.0 reaches exactly this catalogue with ALTER EXTENSION arg UPDATE
-- (arg--0.1.0--0.2.0.sql); tests/upgrade/upgrade.sh compares the two.
--
-- Every pure function is IMMUTABLE STRICT PARALLEL SAFE, so it can feed a generated column and
-- run in parallel plans. COST is in units of cpu_operator_cost (0.0025 of a sequential page
-- read). Reading an 8 kB page sequentially takes about 10 us, so one unit is about 25 ns: the
-- planner then weighs a comparison against the pages it reads as they really compare, and runs
-- a ranking in parallel workers (and walks a GiST index rather than computing arg_global for
-- every row) when that pays. Measured per call in the server (bench/sql_bench.sh: 1,000 generated
-- models at resolution 32, about 7k triangles, on a shared 2-core machine; tests/scale for
-- arg_global) and with Google Benchmark (build/arg_bench):
--   arg_build            24 ms per insert (40 ms for 11k triangles in BM_WholeBuild)  COST 1000000
--   arg_generate_model   20 ms                                                        COST 800000
--   arg_sim, <~>,        48 us per row of a ranking: detoasting the stored value      COST 2000
--     arg_matches          ~15 us, reading its graph ~7 us, matching 7-27 us          COST 600
--   arg_part_match       37 us per candidate (node at level 2; finer levels more)     COST 1500
--   arg_global(_vector)  ~40 us: detoasting the stored value                         COST 1600
--   arg_nodes 68 us, arg_svg 57 us, arg_info 41 us                        COST 2700, 2300, 1600
--   arg_in 250 us, arg_out 200 us (base64 and the full check), arg_recv ~60 us
--                                                                         COST 10000, 8000, 2400

-- complain if script is sourced in psql, rather than via CREATE EXTENSION
\echo Use "CREATE EXTENSION arg" to load this file. \quit

-- The type arg ------------------------------------------------------------------------------

CREATE TYPE arg;

CREATE FUNCTION arg_in(cstring) RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_in' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 10000;

CREATE FUNCTION arg_out(arg) RETURNS cstring
  AS 'MODULE_PATHNAME', 'arg_out' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 8000;

CREATE FUNCTION arg_recv(internal) RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_recv' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 2400;

CREATE FUNCTION arg_send(arg) RETURNS bytea
  AS 'MODULE_PATHNAME', 'arg_send' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE TYPE arg (
  INPUT = arg_in,
  OUTPUT = arg_out,
  RECEIVE = arg_recv,
  SEND = arg_send,
  INTERNALLENGTH = VARIABLE,
  -- Out of line but not compressed, as pgvector does: ranking reads every row's value, and
  -- reading a value uncompressed costs less than half of what pglz decompression does
  -- (measured: 36 against 84 us per row of ORDER BY descr <~> q). Costs twice the space,
  -- little next to the meshes. ALTER TABLE ... SET STORAGE EXTENDED gives compression back.
  STORAGE = external
);

COMMENT ON TYPE arg IS
  'Augmented Reeb Graph of a 3D mesh (text form: arg1: followed by base64 of the binary form)';

-- Equality (byte equality of the deterministic binary form), hashing (of the digest the header
-- stores) and a canonical order (digest, size, bytes: a total order that says nothing about
-- shape; <~> does), so that =, DISTINCT, count(DISTINCT), GROUP BY, UNION and hash or merge
-- joins work.

CREATE FUNCTION arg_eq(arg, arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_eq' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_ne(arg, arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_ne' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_lt(arg, arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_lt' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_le(arg, arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_le' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_gt(arg, arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_gt' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_ge(arg, arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_ge' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_cmp(arg, arg) RETURNS int4
  AS 'MODULE_PATHNAME', 'arg_cmp' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE LEAKPROOF;

CREATE FUNCTION arg_hash(arg) RETURNS int4
  AS 'MODULE_PATHNAME', 'arg_hash' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_hash_extended(arg, int8) RETURNS int8
  AS 'MODULE_PATHNAME', 'arg_hash_extended' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE OPERATOR = (
  LEFTARG = arg, RIGHTARG = arg, FUNCTION = arg_eq,
  COMMUTATOR = =, NEGATOR = <>, RESTRICT = eqsel, JOIN = eqjoinsel, HASHES, MERGES
);

CREATE OPERATOR <> (
  LEFTARG = arg, RIGHTARG = arg, FUNCTION = arg_ne,
  COMMUTATOR = <>, NEGATOR = =, RESTRICT = neqsel, JOIN = neqjoinsel
);

CREATE OPERATOR < (
  LEFTARG = arg, RIGHTARG = arg, FUNCTION = arg_lt,
  COMMUTATOR = >, NEGATOR = >=, RESTRICT = scalarltsel, JOIN = scalarltjoinsel
);

CREATE OPERATOR <= (
  LEFTARG = arg, RIGHTARG = arg, FUNCTION = arg_le,
  COMMUTATOR = >=, NEGATOR = >, RESTRICT = scalarlesel, JOIN = scalarlejoinsel
);

CREATE OPERATOR > (
  LEFTARG = arg, RIGHTARG = arg, FUNCTION = arg_gt,
  COMMUTATOR = <, NEGATOR = <=, RESTRICT = scalargtsel, JOIN = scalargtjoinsel
);

CREATE OPERATOR >= (
  LEFTARG = arg, RIGHTARG = arg, FUNCTION = arg_ge,
  COMMUTATOR = <=, NEGATOR = <, RESTRICT = scalargesel, JOIN = scalargejoinsel
);

CREATE OPERATOR CLASS arg_ops DEFAULT FOR TYPE arg USING btree AS
  OPERATOR 1 <,
  OPERATOR 2 <=,
  OPERATOR 3 =,
  OPERATOR 4 >=,
  OPERATOR 5 >,
  FUNCTION 1 arg_cmp(arg, arg);

CREATE OPERATOR CLASS arg_hash_ops DEFAULT FOR TYPE arg USING hash AS
  OPERATOR 1 = (arg, arg),
  FUNCTION 1 arg_hash(arg),
  FUNCTION 2 arg_hash_extended(arg, int8);

-- The type arg_weights ----------------------------------------------------------------------

CREATE TYPE arg_weights;

CREATE FUNCTION arg_weights_in(cstring) RETURNS arg_weights
  AS 'MODULE_PATHNAME', 'arg_weights_in' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_weights_out(arg_weights) RETURNS cstring
  AS 'MODULE_PATHNAME', 'arg_weights_out' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_weights_recv(internal) RETURNS arg_weights
  AS 'MODULE_PATHNAME', 'arg_weights_recv' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_weights_send(arg_weights) RETURNS bytea
  AS 'MODULE_PATHNAME', 'arg_weights_send' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE TYPE arg_weights (
  INPUT = arg_weights_in,
  OUTPUT = arg_weights_out,
  RECEIVE = arg_weights_recv,
  SEND = arg_weights_send,
  INTERNALLENGTH = 48,
  ALIGNMENT = int4,
  STORAGE = plain
);

COMMENT ON TYPE arg_weights IS
  'weights of matching and SIM: a preset (arg, mrg, graph, shape, colour) and/or key=value pairs '
  '(alpha_l beta_l gamma_l delta_l eps_l alpha_s beta_s lambda_1..lambda_4 graph panorama spectrum '
  'graph_on_proxy norm tung groups, or the readable names loss_area loss_length loss_radius loss_theta '
  'loss_phi area length volume cords curvature colour)';

-- Building ----------------------------------------------------------------------------------

CREATE FUNCTION arg_build(mesh bytea, options text DEFAULT '') RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_build_mesh' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1000000;

COMMENT ON FUNCTION arg_build(bytea, text) IS
  'ARG of a mesh (OFF, OBJ, PLY, STL or GLB, detected); options like ''levels=5 mu=geodesic base_points=128 surface=auto''';

CREATE FUNCTION arg_build(mesh bytea, texture bytea, options text DEFAULT '') RETURNS arg
  AS 'MODULE_PATHNAME', 'arg_build_textured' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1000000;

COMMENT ON FUNCTION arg_build(bytea, bytea, text) IS
  'ARG of a mesh whose texture image (PNG, JPEG, true-colour or grey TGA, uncompressed BMP) is kept outside it, as OBJ does';

-- Keeping an arg column up to date from a bytea column, as an alternative to a generated column:
--   CREATE TRIGGER t BEFORE INSERT OR UPDATE ON tbl FOR EACH ROW
--     EXECUTE FUNCTION arg_index_trigger('mesh', 'descr' [, 'texture' [, 'levels=5 ...']]);
CREATE FUNCTION arg_index_trigger() RETURNS trigger
  AS 'MODULE_PATHNAME', 'arg_index_trigger' LANGUAGE C;

COMMENT ON FUNCTION arg_index_trigger() IS
  'trigger: arg_index_trigger(mesh_column, arg_column [, texture_column [, build_options]]) builds the ARG on INSERT and when the mesh changes';

-- Comparing ---------------------------------------------------------------------------------

CREATE FUNCTION arg_sim(a arg, b arg, weights arg_weights DEFAULT 'arg') RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_sim' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 2000;

COMMENT ON FUNCTION arg_sim(arg, arg, arg_weights) IS
  'SIM(a, b) in [0, 1], 0 for the same shape, symmetric; error 22023 for ARGs of other builder versions or options';

CREATE FUNCTION arg_distance(a arg, b arg) RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_distance' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 2000;

COMMENT ON FUNCTION arg_distance(arg, arg) IS 'arg_sim(a, b) with the default weights; the <~> operator';

CREATE OPERATOR <~> (
  LEFTARG = arg,
  RIGHTARG = arg,
  FUNCTION = arg_distance,
  COMMUTATOR = <~>
);

COMMENT ON OPERATOR <~> (arg, arg) IS 'shape dissimilarity (SIM with default weights), for ORDER BY';

CREATE FUNCTION arg_matches(a arg, b arg, weights arg_weights DEFAULT 'arg')
  RETURNS TABLE (level int, a_node int, b_node int, match_group int, loss float8, sim float8)
  AS 'MODULE_PATHNAME', 'arg_matches' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 600 ROWS 40;

COMMENT ON FUNCTION arg_matches(arg, arg, arg_weights) IS
  'the node pairs matched to compute arg_sim(a, b, weights); nodes are numbered within their level';

CREATE FUNCTION arg_part_match(query arg, level int, node int, candidate arg,
                               weights arg_weights DEFAULT 'arg')
  RETURNS TABLE (candidate_level int, candidate_node int, score float8)
  AS 'MODULE_PATHNAME', 'arg_part_match' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 1500 ROWS 5;

COMMENT ON FUNCTION arg_part_match(arg, int, int, arg, arg_weights) IS
  'nodes of candidate (at level and the levels next to it) whose parts match node of query at level, best (lowest score) first';

-- Inspecting --------------------------------------------------------------------------------

CREATE FUNCTION arg_nodes(arg)
  RETURNS TABLE (level int, node int, parent int, area real, mu_min real, mu_max real,
                 r real, theta real, phi real, volume real)
  AS 'MODULE_PATHNAME', 'arg_nodes' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 2700 ROWS 60;

COMMENT ON FUNCTION arg_nodes(arg) IS
  'one row per node: level, index within the level, parent''s index within level - 1, and attributes';

CREATE FUNCTION arg_info(arg) RETURNS jsonb
  AS 'MODULE_PATHNAME', 'arg_info' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1600;

COMMENT ON FUNCTION arg_info(arg) IS
  'levels, nodes per level, genus estimate, triangles, build options, builder version and format version of an ARG';

-- STABLE, not IMMUTABLE: the same value needs a rebuild or not depending on the library that is
-- installed, so it must not feed an index or a generated column.
CREATE FUNCTION arg_rebuild_needed(arg) RETURNS bool
  AS 'MODULE_PATHNAME', 'arg_rebuild_needed' LANGUAGE C STABLE STRICT PARALLEL SAFE COST 1600;

COMMENT ON FUNCTION arg_rebuild_needed(arg) IS
  'true when this library would build the ARG differently: an older binary format, or a builder of another major or minor version';

CREATE FUNCTION arg_svg(arg, level int DEFAULT 2) RETURNS text
  AS 'MODULE_PATHNAME', 'arg_svg' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 2300;

COMMENT ON FUNCTION arg_svg(arg, int) IS 'the Reeb graph of one level as a self-contained SVG picture';

-- Fixtures ----------------------------------------------------------------------------------

CREATE FUNCTION arg_generate_model(class text, variant int, resolution int DEFAULT 32)
  RETURNS bytea
  AS 'MODULE_PATHNAME', 'arg_generate_model' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE
  COST 800000;

COMMENT ON FUNCTION arg_generate_model(text, int, int) IS
  'OFF bytes of a deterministic generated model: class vase, cup, amphora, torus, fourleg, human, table, chair or octopus; any variant in [0, 999999]; resolution in [8, 128] grid cells';

-- About -------------------------------------------------------------------------------------

CREATE FUNCTION arg_version() RETURNS text
  AS 'MODULE_PATHNAME', 'arg_version' LANGUAGE C STABLE PARALLEL SAFE;

COMMENT ON FUNCTION arg_version() IS 'version of the arg extension and of the binary format it writes';

-- Large catalogues: two-stage search ----------------------------------------------------------
--
-- A compact global descriptor per ARG (92 values of the core's search descriptor: the panorama's
-- lowest frequencies, the log of the first eigenvalues, curvature, node counts, the largest node
-- areas and colour, each block scaled by a weight tuned on the labelled sets) as a cube point,
-- so that a GiST index (contrib cube; with btree_gist for filter columns) returns candidates in
-- order of the taxicab distance <#>, which arg_sim then ranks exactly:
--
--   CREATE INDEX ON objects USING gist (arg_global(descr));
--   WITH candidates AS MATERIALIZED (
--     SELECT id, descr FROM objects
--     ORDER BY arg_global(descr) <#> arg_global($1) LIMIT 1000)
--   SELECT id, descr <~> $1 AS sim FROM candidates ORDER BY sim LIMIT 10;
--
-- In 92 dimensions GiST boxes overlap and a KNN scan reads much of the index; scanning a stored
-- column (glob cube GENERATED ALWAYS AS (arg_global(descr)) STORED; ORDER BY glob <#> ...) is
-- faster for hundreds of candidates (docs/BENCHMARKS.md "Scale").
--
-- Taxicab rather than Euclidean: SIM sums bin-wise minima of histograms and the panorama's
-- distance is a taxicab one; on the labelled sets it finds more of SIM's nearest (README
-- "Large catalogues"; docs/BENCHMARKS.md "Descriptor choice" for the recall of each).

CREATE FUNCTION arg_global_vector(arg) RETURNS float8[]
  AS 'MODULE_PATHNAME', 'arg_global_vector' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1600;

COMMENT ON FUNCTION arg_global_vector(arg) IS
  'the 92-value global descriptor of an ARG (the panorama''s lowest frequencies, eigenvalues and level sums), for candidate search';

-- A C function rather than SQL over cube(float8[]): no search_path lookup at run time (an index
-- expression must also work where pg_restore empties the search_path), one call per row. The
-- value is built as contrib/cube's public header (cubedata.h) lays it out, and equals
-- cube(arg_global_vector(a)).
CREATE FUNCTION arg_global(arg) RETURNS cube
  AS 'MODULE_PATHNAME', 'arg_global' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1600;

COMMENT ON FUNCTION arg_global(arg) IS
  'the global descriptor as a cube point: index it with GiST and order candidates by <#> (taxicab)';

-- A search's second stage (README "Large catalogues"): what SIM reads besides the nodes (the
-- panorama and the spectrum, as the value holds them) and the descriptor's graph blocks, about
-- 2.6 kB. Between the descriptor's candidates and SIM, arg_sketch_distance ranks thousands of
-- candidates in tens of milliseconds, so that SIM ranks only the few hundred nearest.
CREATE TYPE arg_sketch;

CREATE FUNCTION arg_sketch_in(cstring) RETURNS arg_sketch
  AS 'MODULE_PATHNAME', 'arg_sketch_in' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_sketch_out(arg_sketch) RETURNS cstring
  AS 'MODULE_PATHNAME', 'arg_sketch_out' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_sketch_recv(internal) RETURNS arg_sketch
  AS 'MODULE_PATHNAME', 'arg_sketch_recv' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE FUNCTION arg_sketch_send(arg_sketch) RETURNS bytea
  AS 'MODULE_PATHNAME', 'arg_sketch_send' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE;

CREATE TYPE arg_sketch (
  INPUT = arg_sketch_in,
  OUTPUT = arg_sketch_out,
  RECEIVE = arg_sketch_recv,
  SEND = arg_sketch_send,
  INTERNALLENGTH = VARIABLE,
  -- Out of line, uncompressed (as arg): in the row, 2.6 kB a sketch would make the heap four
  -- times wider and the first stage's scan of every row 2.5 times slower (docs/BENCHMARKS.md
  -- "Second stage"), for a TOAST fetch of about 8 us a candidate saved.
  STORAGE = external
);

COMMENT ON TYPE arg_sketch IS
  'second-stage search sketch of an ARG: panorama, spectrum and graph summary (text form: sketch1: followed by base64)';

CREATE FUNCTION arg_sketch(arg) RETURNS arg_sketch
  AS 'MODULE_PATHNAME', 'arg_sketch' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 1600;

COMMENT ON FUNCTION arg_sketch(arg) IS
  'the sketch of an ARG for the second stage of a search: store it (GENERATED ALWAYS AS (arg_sketch(descr)) STORED) and order candidates by arg_sketch_distance';

CREATE FUNCTION arg_sketch_distance(a arg_sketch, b arg_sketch, weights arg_weights DEFAULT 'arg')
  RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_sketch_distance' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 20;

COMMENT ON FUNCTION arg_sketch_distance(arg_sketch, arg_sketch, arg_weights) IS
  'SIM with its graph term replaced by a summary''s distance: the panorama and spectrum terms exactly as arg_sim weighs them; orders candidates before <~>';

-- arg_sketch_distance with the default weights, as the operator <~> between sketches: what an
-- arg_ivf index orders by.
CREATE FUNCTION arg_sketch_dist(arg_sketch, arg_sketch) RETURNS float8
  AS 'MODULE_PATHNAME', 'arg_sketch_dist' LANGUAGE C IMMUTABLE STRICT PARALLEL SAFE COST 20;

COMMENT ON FUNCTION arg_sketch_dist(arg_sketch, arg_sketch) IS
  'arg_sketch_distance(a, b) with the default weights; the <~> operator of arg_sketch';

CREATE OPERATOR <~> (
  LEFTARG = arg_sketch,
  RIGHTARG = arg_sketch,
  FUNCTION = arg_sketch_dist,
  COMMUTATOR = <~>
);

COMMENT ON OPERATOR <~> (arg_sketch, arg_sketch) IS
  'sketch distance (arg_sketch_distance with default weights), for ORDER BY and arg_ivf indexes';

-- An approximate index of sketches (README "Large catalogues"): an inverted file whose cells
-- are centred on sketches of a sample of the rows. ORDER BY sketch <~> query reads the lists of
-- the arg.ivf_probes cells nearest to the query, not the whole table. WITH (lists = n) sets
-- the cells (default: the square root of the rows at build).
CREATE FUNCTION arg_ivf_handler(internal) RETURNS index_am_handler
  AS 'MODULE_PATHNAME', 'arg_ivf_handler' LANGUAGE C;

CREATE ACCESS METHOD arg_ivf TYPE INDEX HANDLER arg_ivf_handler;

COMMENT ON ACCESS METHOD arg_ivf IS
  'approximate nearest sketches: ORDER BY sketch <~> query reads the arg.ivf_probes nearest cells';

CREATE OPERATOR CLASS arg_sketch_ops DEFAULT FOR TYPE arg_sketch USING arg_ivf AS
  OPERATOR 1 <~> (arg_sketch, arg_sketch) FOR ORDER BY float_ops;

-- The two- or three-stage query over any table, as one call:
--   SELECT (o).id, (o).title, sim
--   FROM arg_knn(NULL::objects, 'descr', $1, 10, filter => '{"museum": "M7"}') AS k(o, sim);
-- tbl: NULL cast to the table's row type (it names the table, as in jsonb_populate_record);
-- col: the arg column; candidates: how many the first stage returns (default 100 k, at least
-- 1000, or with a sketch 300 k, at least 3000; never fewer than k); filter: a jsonb object of
-- column = value conditions (a JSON null means IS NULL), quoted as identifiers and literals,
-- never read as SQL; descriptor: a cube column holding arg_global(col) (say GENERATED ALWAYS
-- AS (arg_global(descr)) STORED), scanned instead of computing arg_global(col) per row.
-- Without it the candidates come from a GiST index on arg_global(col) (or on (museum,
-- arg_global(col)) with btree_gist): the function turns enable_seqscan off for its query, as
-- the planner prices each index probe like a random read and would otherwise compute
-- arg_global for every row once candidates is more than a few percent of the table.
-- sketch: an arg_sketch column holding arg_sketch(col); the candidates are then ordered by
-- arg_sketch_distance and only the shortlist nearest (default 20 k, at least 200) are ranked
-- by <~>, which finds SIM's nearest among many more candidates for the same time (docs/
-- BENCHMARKS.md "Second stage: the sketch"); a candidate whose sketch is NULL comes last.
-- Under a filter it still returns min(k, matching rows) rows.
-- Ties in sim are broken by the arg's canonical order.
CREATE FUNCTION arg_knn(tbl anyelement, col name, query arg, k int DEFAULT 10,
                        candidates int DEFAULT NULL, filter jsonb DEFAULT NULL,
                        descriptor name DEFAULT NULL, sketch name DEFAULT NULL,
                        shortlist int DEFAULT NULL)
  RETURNS TABLE (obj anyelement, sim float8)
  LANGUAGE plpgsql STABLE
  SET search_path FROM CURRENT
  ROWS 10
AS $$
DECLARE
  relid oid;
  kind "char";
  children bool;
  conditions text := '';
  nearest text;
  gq cube;
  sq arg_sketch;
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
  gq := arg_global(query);
  IF NOT EXISTS (SELECT FROM pg_attribute a WHERE a.attrelid = relid AND a.attname = col
                   AND a.attnum > 0 AND NOT a.attisdropped AND a.atttypid = pg_typeof(query)) THEN
    RAISE EXCEPTION 'arg_knn: % has no column % of type arg', relid::regclass, quote_ident(col)
      USING ERRCODE = 'undefined_column';
  END IF;
  IF descriptor IS NOT NULL AND NOT EXISTS (
       SELECT FROM pg_attribute a WHERE a.attrelid = relid AND a.attname = descriptor
         AND a.attnum > 0 AND NOT a.attisdropped AND a.atttypid = pg_typeof(gq)) THEN
    RAISE EXCEPTION 'arg_knn: % has no column % of type cube', relid::regclass, quote_ident(descriptor)
      USING ERRCODE = 'undefined_column';
  END IF;
  IF sketch IS NOT NULL THEN
    sq := arg_sketch(query);
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
         WHERE t.%1$I IS NOT NULL ORDER BY t.%3$I <~> $2 LIMIT $3),
       cand AS (
         SELECT idx.r FROM idx
         UNION ALL
         SELECT ROW(t.*)::%2$s FROM %2$s t
         WHERE (SELECT count(*) FROM idx) < $4 AND t.%1$I IS NOT NULL
           AND (t.tableoid, t.ctid) NOT IN (SELECT idx.rel, idx.tid FROM idx))
       SELECT c.r, (c.r).%1$I <~> $1 AS sim FROM cand c ORDER BY sim, (c.r).%1$I LIMIT $4',
      col, relid::regclass, sketch)
    USING query, sq, greatest(coalesce(shortlist, greatest(20 * k, 200)), k), k;
    PERFORM set_config('enable_seqscan', seqscan, true);
    RETURN;
  END IF;
  IF descriptor IS NULL THEN
    nearest := format('arg_global(t.%I)', col);
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
                        ORDER BY %4$s <#> $2 LIMIT $3))', relid::regclass, col, conditions, nearest);
  ELSE
    stages := format('SELECT t.* FROM %s t WHERE t.%I IS NOT NULL%s ORDER BY %s <#> $2 LIMIT $3',
                     relid::regclass, col, conditions, nearest);
  END IF;
  IF sketch IS NOT NULL THEN
    stages := format('SELECT t.* FROM (%s) t ORDER BY arg_sketch_distance(t.%I, $5) LIMIT $6',
                     stages, sketch);
  END IF;
  -- The row value is formed only for the candidates, after the LIMIT: a whole-row reference
  -- in the scan itself would detoast every ARG the first stages look at.
  RETURN QUERY EXECUTE format(
    'SELECT c.r, (c.r).%1$I <~> $1 AS sim
     FROM (SELECT ROW(s.*)::%2$s AS r FROM (%3$s) s) c
     ORDER BY sim, (c.r).%1$I LIMIT $4',
    col, relid::regclass, stages)
  USING query, gq,
        greatest(coalesce(candidates, CASE WHEN sketch IS NULL THEN greatest(100 * k, 1000)
                                           ELSE greatest(300 * k, 3000) END), k),
        k, sq, greatest(coalesce(shortlist, greatest(20 * k, 200)), k);
  PERFORM set_config('enable_seqscan', seqscan, true);
END
$$;

COMMENT ON FUNCTION arg_knn(anyelement, name, arg, int, int, jsonb, name, name, int) IS
  'search in stages: the candidates nearest by arg_global (GiST index, or a stored descriptor column) by <#>, then with a stored arg_sketch column the shortlist nearest by arg_sketch_distance (straight from an arg_ivf index on it, without filter or descriptor), ranked exactly by <~>; returns (row, sim), best first';
