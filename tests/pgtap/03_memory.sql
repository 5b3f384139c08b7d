-- A backend's own memory stays flat under repeated work: after a warm-up, a thousand more
-- rankings, part matches and builds in the same session leave its private resident memory
-- (RssAnon, read from /proc as a superuser) where it was. A leak of one graph per call would
-- add tens of megabytes. The builds cycle through the same 30 models in the warm-up and after
-- it: a first build of a larger model raises the heap's high-water mark, which is not a leak.
-- The allocator keeps or returns a freed block of a few megabytes depending on what lies above
-- it, so resident memory swings by that much between two equal rounds: the baseline is the
-- highest reading of the warm-up's rounds, and a leak shows as growth past it.
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SELECT plan(3);

CREATE FUNCTION pg_temp.rss_anon_kb() RETURNS bigint LANGUAGE sql AS $$
  SELECT substring(pg_read_file('/proc/self/status') FROM 'RssAnon:\s+(\d+)')::bigint $$;

CREATE TEMP TABLE catalogue AS
SELECT row_number() OVER () AS id, arg_build(arg_generate_model(c, v, 12)) AS descr
FROM unnest(ARRAY['vase', 'cup', 'human', 'chair', 'fourleg']) c, generate_series(0, 19) v;

-- rounds ranking queries over the catalogue, a part match and a build every tenth round.
CREATE FUNCTION pg_temp.work(rounds int) RETURNS bigint LANGUAGE plpgsql AS $$
DECLARE
  n bigint := 0;
BEGIN
  FOR i IN 1 .. rounds LOOP
    n := n + (SELECT count(*) FROM (SELECT id FROM catalogue
                                    ORDER BY descr <~> (SELECT descr FROM catalogue WHERE id = 1 + i % 100)
                                    LIMIT 10) s);
    IF i % 10 = 0 THEN
      n := n + (SELECT count(*) FROM catalogue a, arg_part_match(a.descr, 2, 0,
                  (SELECT descr FROM catalogue WHERE id = 1 + (i / 10) % 100)) WHERE a.id = 1 + i % 100);
      n := n + (SELECT count(*) FROM arg_nodes(arg_build(arg_generate_model('cup', (i / 10) % 30, 8))));
    END IF;
  END LOOP;
  RETURN n;
END $$;

CREATE TEMP TABLE readings (kb bigint);
CREATE FUNCTION pg_temp.warm_up(rounds int) RETURNS bigint LANGUAGE plpgsql AS $$
DECLARE n bigint := 0;
BEGIN
  FOR i IN 1 .. 3 LOOP
    n := n + pg_temp.work(rounds);
    INSERT INTO readings SELECT pg_temp.rss_anon_kb();
  END LOOP;
  RETURN n;
END $$;
SELECT cmp_ok(pg_temp.warm_up(300), '>', 0::bigint, 'warm-up: 3 x (300 rankings, 30 part matches and 30 builds)');
CREATE TEMP TABLE before AS SELECT max(kb) AS kb FROM readings;
SELECT cmp_ok(pg_temp.work(1000), '>', 0::bigint, 'then 1,000 rankings, 100 part matches and 100 builds');
SELECT cmp_ok(pg_temp.rss_anon_kb() - (SELECT kb FROM before), '<', 2048::bigint,
              format('1,000 more rankings, 100 part matches and 100 builds: private memory %s kB -> %s kB',
                     (SELECT kb FROM before), pg_temp.rss_anon_kb()));

SELECT * FROM finish();
ROLLBACK;
