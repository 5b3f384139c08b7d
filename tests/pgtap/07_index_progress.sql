-- CREATE INDEX ... USING arg_ivf reports its build in pg_stat_progress_create_index: the phase
-- names of the access method, and while another session builds an index on 19,200 rows, the
-- filing phase with its rows done out of the total. dblink runs the build in that other session;
-- this one polls the view (pg_stat_clear_snapshot: each read sees the other backend now).
-- No transaction around the file: the other session must see the table; it is dropped at the end.
\set ON_ERROR_STOP 1
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
CREATE EXTENSION IF NOT EXISTS dblink;
SELECT plan(6);

SELECT is(array_agg(pg_indexam_progress_phasename(am.oid, p) ORDER BY p),
          ARRAY['initializing', 'sampling rows', 'choosing centres', 'filing rows'],
          'the build phases of arg_ivf have names')
FROM pg_am am, generate_series(1, 4) p WHERE am.amname = 'arg_ivf';

CREATE TABLE progress_models AS
SELECT arg_build(arg_generate_model(c, v, 12)) AS descr
FROM unnest(ARRAY['vase', 'cup', 'torus', 'chair', 'human', 'fourleg']) c, generate_series(0, 3) v;
CREATE TABLE progress_rows AS SELECT m.descr FROM progress_models m, generate_series(1, 800);
CREATE TEMP TABLE progress_seen AS
SELECT phase, tuples_total, tuples_done FROM pg_stat_progress_create_index WHERE false;

DO $$
BEGIN
  PERFORM dblink_connect('progress', format('host=localhost port=%s dbname=%s user=%s',
                         current_setting('port'), current_database(), current_user));
  PERFORM dblink_send_query('progress',
                            'CREATE INDEX progress_rows_descr ON progress_rows USING arg_ivf (descr)');
  LOOP
    PERFORM pg_stat_clear_snapshot();
    INSERT INTO progress_seen
    SELECT phase, tuples_total, tuples_done FROM pg_stat_progress_create_index
    WHERE relid = 'progress_rows'::regclass;
    EXIT WHEN dblink_is_busy('progress') = 0;
    PERFORM pg_sleep(0.02);
  END LOOP;
END $$;
SELECT is((SELECT status FROM dblink_get_result('progress') AS r(status text)), 'CREATE INDEX',
          'the other session built the index');
DO $$ BEGIN PERFORM dblink_disconnect('progress'); END $$;

SELECT ok(EXISTS (SELECT FROM progress_seen WHERE phase = 'building index: filing rows'),
          'the view showed the filing phase');
SELECT is((SELECT DISTINCT tuples_total FROM progress_seen WHERE phase = 'building index: filing rows'),
          19200::bigint, 'its total is the table''s rows');
SELECT ok((SELECT max(tuples_done) BETWEEN 1 AND 19200 FROM progress_seen
           WHERE phase = 'building index: filing rows'),
          format('rows filed rose while it ran (%s readings, at most %s filed)',
                 (SELECT count(*) FROM progress_seen WHERE phase = 'building index: filing rows'),
                 (SELECT max(tuples_done) FROM progress_seen WHERE phase = 'building index: filing rows')));
SELECT is((SELECT entries FROM arg_index_check('progress_rows_descr')), 19200::bigint,
          'the index holds every row');

SELECT * FROM finish();
DROP TABLE progress_rows, progress_models;
