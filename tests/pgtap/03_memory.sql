-- A backend's own memory stays flat under repeated work: after a warm-up, 1,200 more rankings,
-- part matches and builds in the same session leave its private resident memory (RssAnon, read
-- from /proc as a superuser) where it was. A leak of one graph per call would add tens of
-- megabytes. The builds cycle through the same 30 models in the warm-up and after it: a first
-- build of a larger model raises the heap's high-water mark, which is not a leak.
-- The allocator keeps a freed block of tens of megabytes resident once a later long-lived
-- allocation (a catalogue cache block, say) lands above it: a single step, on some runs in the
-- warm-up and on others after it (a CI run saw 20.9 MB -> 42 MB in one round, then flat), and
-- swings of a few megabytes between equal rounds. A leak raises every reading, such a step one:
-- the test reads memory after each of six rounds, leaves out the largest rise between two
-- consecutive readings, and allows 4 MB from the warm-up's highest reading to the lowest of the
-- last three (a leak of 3 kB a
-- ranking would pass one step but not five). Nothing between the rounds creates or truncates a
-- table, so that no new catalogue memory lands in the measured part.
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

CREATE TEMP TABLE readings (n serial, phase text, kb bigint);
CREATE FUNCTION pg_temp.rounds(phase text, count int, rounds int) RETURNS bigint LANGUAGE plpgsql AS $$
DECLARE n bigint := 0;
BEGIN
  FOR i IN 1 .. count LOOP
    n := n + pg_temp.work(rounds);
    INSERT INTO readings (phase, kb) SELECT phase, pg_temp.rss_anon_kb();
  END LOOP;
  RETURN n;
END $$;
SELECT cmp_ok(pg_temp.rounds('warm-up', 3, 300), '>', 0::bigint, 'warm-up: 3 x (300 rankings, 30 part matches and 30 builds)');
SELECT cmp_ok(pg_temp.rounds('after', 6, 200), '>', 0::bigint, 'then 6 x (200 rankings, 20 part matches and 20 builds)');
-- rise: the lowest of the last three readings over the warm-up's highest; step: the largest rise
-- from one reading to the next, from the warm-up's last reading on.
WITH w AS (SELECT max(kb) AS kb FROM readings WHERE phase = 'warm-up'),
     a AS (SELECT (SELECT min(kb) FROM (SELECT kb FROM readings ORDER BY n DESC LIMIT 3) l) - w.kb AS rise,
                  (SELECT greatest(0, max(kb - prev)) FROM
                     (SELECT kb, lag(kb) OVER (ORDER BY n) AS prev, phase FROM readings) r
                   WHERE phase = 'after' AND prev IS NOT NULL) AS step
           FROM w)
SELECT cmp_ok(a.rise - a.step, '<', 4096::bigint,
              format('1,200 more rankings, 120 part matches and 120 builds: private memory %s kB -> %s kB, '
                     'largest single step %s kB left out (readings %s)',
                     w.kb, w.kb + a.rise, a.step,
                     (SELECT string_agg(kb::text, ', ' ORDER BY n) FROM readings)))
FROM a, w;

SELECT * FROM finish();
ROLLBACK;
