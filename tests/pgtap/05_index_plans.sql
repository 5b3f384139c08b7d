-- The planner's choice between an arg_ivf index on an arg column and brute force: an iterative
-- search passes over the rows a filter rejects, one SIM each, so under a filter that keeps few
-- rows (with a b-tree on its column) ranking those rows by brute force is cheaper, and the plan
-- says so; unfiltered, or under a filter that keeps most rows, the index is taken. One
-- candidate a batch makes the index's first batch cheap, so only the charge for the rejected
-- rows can turn the planner away from it.
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SELECT plan(6);

CREATE TABLE plans_models AS
SELECT c AS class, arg_build(arg_generate_model(c, 0, 12)) AS descr
FROM unnest(ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table', 'chair']) c;
-- 200 rows: 25 of each model; museum M0 holds 16 of them (8%), M1..M4 the rest.
CREATE TABLE plans_objects AS
SELECT row_number() OVER () AS id, 'M' || CASE WHEN n % 20 = 0 THEN 0 ELSE 1 + n % 4 END AS museum,
       m.descr
FROM generate_series(0, 24) n, plans_models m;
CREATE INDEX plans_objects_museum ON plans_objects (museum);
CREATE INDEX plans_objects_descr ON plans_objects USING arg_ivf (descr) WITH (lists = 10);
ANALYZE plans_objects;
SET LOCAL arg.ivf_candidates = 1;

CREATE FUNCTION pg_temp.plan_of(filter text) RETURNS text LANGUAGE plpgsql AS $$
DECLARE
  line text;
  plan text := '';
BEGIN
  FOR line IN EXECUTE format('EXPLAIN (COSTS OFF) SELECT id FROM plans_objects WHERE %s '
                             'ORDER BY descr <~> (SELECT descr FROM plans_models WHERE class = %L) '
                             'LIMIT 3', filter, 'cup') LOOP
    plan := plan || line || E'\n';
  END LOOP;
  RETURN plan;
END $$;

SELECT is((SELECT count(*) FROM plans_objects WHERE museum = 'M0'), 16::bigint,
          'the filter museum = M0 keeps 16 of the 200 rows');
SELECT matches(pg_temp.plan_of('true'), 'Index Scan using plans_objects_descr',
               'unfiltered, ORDER BY descr <~> q LIMIT 3 takes the arg index');
SELECT matches(pg_temp.plan_of($$museum <> 'M0'$$), 'Index Scan using plans_objects_descr',
               'a filter that keeps 92% of the rows: the arg index');
SELECT doesnt_match(pg_temp.plan_of($$museum = 'M0'$$), 'plans_objects_descr',
                    'a filter that keeps 8% of the rows: not the arg index');
SELECT matches(pg_temp.plan_of($$museum = 'M0'$$), 'Sort Key: \(\(plans_objects.descr <~>',
               '... but brute force: the rows that pass the filter sorted by <~>');
SET LOCAL arg.iterative_scan = off;
SELECT matches(pg_temp.plan_of('true'), 'Index Scan using plans_objects_descr',
               'with arg.iterative_scan off the unfiltered query still takes the arg index');

SELECT * FROM finish();
ROLLBACK;
