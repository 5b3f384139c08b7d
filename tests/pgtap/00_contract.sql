-- The SQL contract of the extension: its objects, their signatures and their markings.
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SELECT plan(205);

SELECT has_extension('arg', 'the arg extension is installed');
SELECT has_type('arg', 'type arg exists');
SELECT has_type('arg_weights', 'type arg_weights exists');
SELECT has_type('arg_sketch', 'type arg_sketch exists');
-- A sketch is kept out of line, uncompressed: the heap stays narrow for the first stage's scan.
SELECT is((SELECT typstorage FROM pg_type WHERE typname = 'arg_sketch'), 'e'::"char",
          'arg_sketch is stored out of line, uncompressed');

-- arg is a varlena stored out of line uncompressed; arg_weights a fixed 48 bytes; neither has a
-- type modifier.
SELECT is((SELECT typlen FROM pg_type WHERE typname = 'arg'), -1::int2, 'arg is variable-length');
SELECT is((SELECT typstorage FROM pg_type WHERE typname = 'arg'), 'e'::"char",
          'arg is stored out of line, uncompressed');
SELECT is((SELECT typlen FROM pg_type WHERE typname = 'arg_weights'), 48::int2,
          'arg_weights is a fixed-length value of 48 bytes');
SELECT ok((SELECT NOT typbyval FROM pg_type WHERE typname = 'arg_weights'),
          'arg_weights is passed by reference');
SELECT is((SELECT count(*)::int FROM pg_type
           WHERE typname IN ('arg', 'arg_weights') AND typmodin = 0 AND typmodout = 0), 2,
          'neither type takes a type modifier');
SELECT is((SELECT count(*)::int FROM pg_type
           WHERE typname IN ('arg', 'arg_weights') AND typreceive <> 0 AND typsend <> 0), 2,
          'both types have binary input and output');

-- Operators.
SELECT has_operator('arg', '<~>', 'arg', 'double precision', 'operator arg <~> arg exists');
SELECT has_operator('arg', op, 'arg', 'boolean', 'operator arg ' || op || ' arg exists')
FROM unnest(ARRAY['=', '<>', '<', '<=', '>', '>=']) AS op;
SELECT ok((SELECT oprcanhash FROM pg_operator
           WHERE oprname = '=' AND oprleft = 'arg'::regtype AND oprright = 'arg'::regtype),
          '= on arg can hash (hash joins, hashed DISTINCT and GROUP BY)');
SELECT has_operator('arg_sketch', '<~>', 'arg_sketch', 'double precision',
                    'operator arg_sketch <~> arg_sketch exists');
SELECT has_opclass('arg_hash_ops', 'hash operator class for arg exists');
SELECT has_opclass('arg_ops', 'btree operator class for arg exists');
SELECT ok(EXISTS (SELECT 1 FROM pg_opclass c JOIN pg_am a ON a.oid = c.opcmethod
                  WHERE c.opcname = 'arg_hash_ops' AND a.amname = 'hash' AND c.opcdefault),
          'arg_hash_ops is the default hash operator class of arg');
SELECT ok(EXISTS (SELECT 1 FROM pg_opclass c JOIN pg_am a ON a.oid = c.opcmethod
                  WHERE c.opcname = 'arg_ops' AND a.amname = 'btree' AND c.opcdefault),
          'arg_ops is the default btree operator class of arg');

-- The approximate index of sketches: an index access method ordering by <~>, whose default
-- operator class passes its own check; arg.ivf_probes sets how many cells a search reads.
SELECT ok(EXISTS (SELECT 1 FROM pg_am WHERE amname = 'arg_ivf' AND amtype = 'i'),
          'index access method arg_ivf exists');
SELECT ok(EXISTS (SELECT 1 FROM pg_opclass c JOIN pg_am a ON a.oid = c.opcmethod
                  WHERE c.opcname = 'arg_sketch_ops' AND a.amname = 'arg_ivf' AND c.opcdefault
                    AND c.opcintype = 'arg_sketch'::regtype),
          'arg_sketch_ops is the default arg_ivf operator class of arg_sketch');
SELECT ok((SELECT amvalidate(oid) FROM pg_opclass WHERE opcname = 'arg_sketch_ops'),
          'arg_sketch_ops passes arg_ivf''s operator class check');
SELECT ok(EXISTS (SELECT 1 FROM pg_amop o JOIN pg_opclass c ON c.opcfamily = o.amopfamily
                  WHERE c.opcname = 'arg_sketch_ops' AND o.amoppurpose = 'o'
                    AND o.amopopr = '<~>(arg_sketch,arg_sketch)'::regoperator),
          'arg_sketch_ops orders by <~>');
SELECT is(current_setting('arg.ivf_probes'), '4', 'arg.ivf_probes defaults to 4 cells');

-- Every function of the SQL surface, with its signature and return type. Pure functions are
-- IMMUTABLE STRICT PARALLEL SAFE, so they work in generated columns and parallel plans.
CREATE TEMP TABLE surface (sig regprocedure PRIMARY KEY, returns text, pure bool);
INSERT INTO surface VALUES
  ('arg_in(cstring)', 'arg', true),
  ('arg_out(arg)', 'cstring', true),
  ('arg_recv(internal)', 'arg', true),
  ('arg_send(arg)', 'bytea', true),
  ('arg_eq(arg,arg)', 'boolean', true),
  ('arg_ne(arg,arg)', 'boolean', true),
  ('arg_lt(arg,arg)', 'boolean', true),
  ('arg_le(arg,arg)', 'boolean', true),
  ('arg_gt(arg,arg)', 'boolean', true),
  ('arg_ge(arg,arg)', 'boolean', true),
  ('arg_cmp(arg,arg)', 'integer', true),
  ('arg_hash(arg)', 'integer', true),
  ('arg_hash_extended(arg,bigint)', 'bigint', true),
  ('arg_weights_in(cstring)', 'arg_weights', true),
  ('arg_weights_out(arg_weights)', 'cstring', true),
  ('arg_weights_recv(internal)', 'arg_weights', true),
  ('arg_weights_send(arg_weights)', 'bytea', true),
  ('arg_build(bytea,text)', 'arg', true),
  ('arg_build(bytea,bytea,text)', 'arg', true),
  ('arg_sim(arg,arg,arg_weights)', 'double precision', true),
  ('arg_distance(arg,arg)', 'double precision', true),
  ('arg_sim_terms(arg,arg,arg_weights)',
   'TABLE(term text, weight double precision, value double precision, contribution double precision)',
   true),
  ('arg_matches(arg,arg,arg_weights)',
   'TABLE(level integer, a_node integer, b_node integer, match_group integer, loss double precision, sim double precision)',
   true),
  ('arg_part_match(arg,integer,integer,arg,arg_weights)',
   'TABLE(candidate_level integer, candidate_node integer, score double precision)', true),
  ('arg_nodes(arg)',
   'TABLE(level integer, node integer, parent integer, area real, mu_min real, mu_max real, r real, theta real, phi real, volume real)',
   true),
  ('arg_info(arg)', 'jsonb', true),
  ('arg_svg(arg,integer)', 'text', true),
  ('arg_generate_model(text,integer,integer)', 'bytea', true),
  ('arg_global_vector(arg)', 'double precision[]', true),
  ('arg_global(arg)', 'cube', true),
  ('arg_sketch_in(cstring)', 'arg_sketch', true),
  ('arg_sketch_out(arg_sketch)', 'cstring', true),
  ('arg_sketch_recv(internal)', 'arg_sketch', true),
  ('arg_sketch_send(arg_sketch)', 'bytea', true),
  ('arg_sketch(arg)', 'arg_sketch', true),
  ('arg_sketch_distance(arg_sketch,arg_sketch,arg_weights)', 'double precision', true),
  ('arg_sketch_dist(arg_sketch,arg_sketch)', 'double precision', true),
  ('arg_ivf_handler(internal)', 'index_am_handler', false),
  ('arg_index_check(regclass)', 'record', false),
  ('arg_knn(anyelement,name,arg,integer,integer,jsonb,name,name,integer)',
   'TABLE(obj anyelement, sim double precision)', false),
  ('arg_index_trigger()', 'trigger', false),
  ('arg_rebuild_needed(arg)', 'boolean', false),
  ('arg_version()', 'text', false);

SELECT set_eq(
  $$ SELECT p.oid::regprocedure::text FROM pg_proc p
     JOIN pg_depend d ON d.objid = p.oid AND d.classid = 'pg_proc'::regclass AND d.deptype = 'e'
     JOIN pg_extension e ON e.oid = d.refobjid WHERE e.extname = 'arg' $$,
  $$ SELECT sig::text FROM surface $$,
  'the extension has exactly the functions of its documented surface');

SELECT is(pg_get_function_result(sig), returns, sig::text || ' returns ' || returns)
FROM surface ORDER BY sig::text;

-- (Set-returning functions return TABLE(...): one row per match, part or node.)
SELECT is(p.provolatile, 'i', s.sig::text || ' is IMMUTABLE')
FROM surface s JOIN pg_proc p ON p.oid = s.sig WHERE s.pure ORDER BY s.sig::text;
SELECT ok(p.proisstrict, s.sig::text || ' is STRICT')
FROM surface s JOIN pg_proc p ON p.oid = s.sig WHERE s.pure ORDER BY s.sig::text;
SELECT is(p.proparallel, 's', s.sig::text || ' is PARALLEL SAFE')
FROM surface s JOIN pg_proc p ON p.oid = s.sig WHERE s.pure ORDER BY s.sig::text;

SELECT volatility_is('arg_index_trigger', '{}'::name[], 'volatile',
                     'arg_index_trigger() is a volatile trigger function');
SELECT volatility_is('arg_version', '{}'::name[], 'stable', 'arg_version() is STABLE');
-- Its answer changes with the library installed, so it must not feed an index.
SELECT volatility_is('arg_rebuild_needed', '{arg}'::name[], 'stable', 'arg_rebuild_needed(arg) is STABLE');
SELECT is((SELECT provolatile FROM pg_proc
           WHERE oid = 'arg_knn(anyelement,name,arg,integer,integer,jsonb,name,name,integer)'::regprocedure), 's',
          'arg_knn (it reads a table) is STABLE');

-- Defaults: weights default to the arg preset (stored as its canonical text), options to none,
-- the generator's resolution to 32.
SELECT is(pg_get_function_arguments('arg_sim(arg,arg,arg_weights)'::regprocedure),
          'a arg, b arg, weights arg_weights DEFAULT ''' || 'arg'::arg_weights::text || '''::arg_weights',
          'arg_sim''s weights default to the arg preset');
SELECT is(pg_get_function_arguments('arg_build(bytea,text)'::regprocedure),
          'mesh bytea, options text DEFAULT ''''::text', 'arg_build''s options default to none');
SELECT is(pg_get_function_arguments('arg_generate_model(text,integer,integer)'::regprocedure),
          'class text, variant integer, resolution integer DEFAULT 32',
          'arg_generate_model''s resolution defaults to 32');

-- COST reflects measured run times (one unit about 25 ns): a build costs hundreds of
-- comparisons, and a comparison tens of microseconds, so that a ranking runs in parallel workers.
SELECT cmp_ok((SELECT procost::numeric FROM pg_proc WHERE oid = 'arg_build(bytea,text)'::regprocedure), '>=',
              100 * (SELECT procost::numeric FROM pg_proc WHERE oid = 'arg_sim(arg,arg,arg_weights)'::regprocedure),
              'arg_build costs at least a hundred times arg_sim');
SELECT cmp_ok((SELECT procost::numeric FROM pg_proc WHERE oid = 'arg_distance(arg,arg)'::regprocedure), '>=', 1000::numeric,
              'the <~> function is priced as the tens of microseconds it takes');
SELECT is((SELECT procost FROM pg_proc WHERE oid = 'arg_distance(arg,arg)'::regprocedure),
          (SELECT procost FROM pg_proc WHERE oid = 'arg_sim(arg,arg,arg_weights)'::regprocedure),
          '<~> costs what arg_sim costs');

-- Settings: the arg. prefix is reserved; caps only a superuser may raise.
SELECT throws_ok($$ SET arg.no_such_setting = 1 $$, '42602', NULL,
                 'the arg. prefix is reserved: unknown settings are refused');
SELECT is((SELECT count(*)::int FROM pg_settings WHERE name LIKE 'arg.max%' AND context = 'superuser'), 6,
          'the six caps are superuser settings');
-- The SQLSTATE of setting arg.max_build_memory as role `who` (the role reverts with the block).
CREATE FUNCTION pg_temp.set_memory_cap_as(who name) RETURNS text LANGUAGE plpgsql AS $$
BEGIN
  EXECUTE format('SET LOCAL ROLE %I', who);
  SET arg.max_build_memory = '64GB';
  RAISE EXCEPTION 'set';  -- undoes the role and the setting
EXCEPTION WHEN raise_exception THEN
  RETURN '00000';
WHEN others THEN
  RETURN SQLSTATE;
END $$;
CREATE ROLE arg_plain_user NOLOGIN;
SELECT is(pg_temp.set_memory_cap_as('arg_plain_user'), '42501',
          'a user who is not a superuser cannot raise arg.max_build_memory');
SELECT is(pg_temp.set_memory_cap_as(current_user), '00000', 'a superuser can');
SELECT is((SELECT context FROM pg_settings WHERE name = 'arg.query_cache'), 'user',
          'arg.query_cache is a user setting');

-- Building and comparing work on a generated model.
CREATE TEMP TABLE cup AS SELECT arg_generate_model('cup', 0, 16) AS mesh;
SELECT lives_ok($$ SELECT arg_build(mesh) FROM cup $$, 'a generated cup builds');
SELECT is(arg_sim(arg_build(mesh), arg_build(mesh)), 0::float8, 'self-similarity is zero')
FROM cup;
SELECT is(arg_hash(arg_build(mesh)), (arg_hash_extended(arg_build(mesh), 0) & 4294967295)::bit(32)::int,
          'with seed 0, arg_hash_extended agrees with arg_hash (as hash operator classes require)')
FROM cup;

-- arg_sim_terms explains SIM: the shares of graph, panorama and spectrum, added in that order
-- (as sum() adds the rows), are arg_sim to the bit, for every pair of a few models (one with
-- colour), itself included, and every preset; the graph's features add up to 1 - its SIM.
CREATE TEMP TABLE explained AS
SELECT m.name, arg_build(arg_generate_model(m.name, 0, 16)) AS descr
FROM unnest(ARRAY['cup', 'vase', 'human', 'table']) AS m(name);
CREATE TEMP TABLE term_sums AS
SELECT a.name AS a, b.name AS b, p AS preset, arg_sim(a.descr, b.descr, p::arg_weights) AS sim,
       (SELECT sum(contribution) FROM arg_sim_terms(a.descr, b.descr, p::arg_weights)) AS total,
       (SELECT value FROM arg_sim_terms(a.descr, b.descr, p::arg_weights) WHERE term = 'graph') AS graph,
       (SELECT sum(value) FROM arg_sim_terms(a.descr, b.descr, p::arg_weights)
        WHERE term LIKE 'graph.%') AS features
FROM explained a, explained b, unnest(ARRAY['arg', 'mrg', 'graph', 'shape', 'colour']) AS p;
SELECT is((SELECT count(*)::int FROM term_sums WHERE total IS DISTINCT FROM sim), 0,
          'arg_sim_terms: the contributions add up to arg_sim exactly, every pair and preset');
SELECT is((SELECT count(*)::int FROM term_sums WHERE abs(1 - features - graph) > 1e-9 AND graph > 0), 0,
          'arg_sim_terms: the graph''s features add up to 1 - the graph''s SIM');
SELECT is((SELECT count(*)::int FROM term_sums WHERE a <> b AND sim > 0), 4 * 3 * 5,
          'arg_sim_terms was checked on distinct models with SIM above 0');

SELECT * FROM finish();
ROLLBACK;
