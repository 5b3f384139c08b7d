-- A backend's own memory stays flat under repeated work: after a warm-up, a thousand more
-- rankings, part matches and builds in the same session leave its private resident memory
-- (RssAnon, read from /proc as a superuser) where it was. A leak of one graph per call would
-- add tens of megabytes. The builds cycle through the same 30 models in the warm-up and after
-- it: a first build of a larger model raises the heap's high-water mark, which is not a leak.
-- The allocator keeps or returns a freed block of a few megabytes depending on what lies above
-- it, so resident memory swings by that much between two equal rounds, one way or the other.
-- A leak raises every later reading, a swing only some: the test compares the lowest of three
-- readings after the work with the highest of the warm-up's three, and allows 4 MB (swings of
-- up to 3 MB were seen on loaded machines; one leaked query graph per ranking would be about 80 MB).
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

CREATE TEMP TABLE readings (n serial, kb bigint);
CREATE FUNCTION pg_temp.three_rounds(rounds int) RETURNS bigint LANGUAGE plpgsql AS $$
DECLARE n bigint := 0;
BEGIN
  FOR i IN 1 .. 3 LOOP
    n := n + pg_temp.work(rounds);
    INSERT INTO readings (kb) SELECT pg_temp.rss_anon_kb();
  END LOOP;
  RETURN n;
END $$;
SELECT cmp_ok(pg_temp.three_rounds(300), '>', 0::bigint, 'warm-up: 3 x (300 rankings, 30 part matches and 30 builds)');
CREATE TEMP TABLE before AS SELECT max(kb) AS kb FROM readings;
TRUNCATE readings;
SELECT cmp_ok(pg_temp.three_rounds(400), '>', 0::bigint, 'then 3 x (400 rankings, 40 part matches and 40 builds)');
SELECT cmp_ok((SELECT min(kb) FROM readings) - (SELECT kb FROM before), '<', 4096::bigint,
              format('1,200 more rankings, 120 part matches and 120 builds: private memory %s kB -> %s kB (lowest of %s)',
                     (SELECT kb FROM before), (SELECT min(kb) FROM readings),
                     (SELECT string_agg(kb::text, ', ' ORDER BY n) FROM readings)));

SELECT * FROM finish();
ROLLBACK;
