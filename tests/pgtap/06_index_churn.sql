-- Space in an arg_ivf index after churn: about half the rows deleted, VACUUM, as many inserted
-- again, twice; inserts fill the room VACUUM freed, so the index stays within 1.3 times the size
-- a fresh build of the same rows takes (REINDEX), and arg_index_check finds every row once.
-- No transaction around the file: VACUUM cannot run in one; the tables are dropped at the end.
\set ON_ERROR_STOP 1
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SELECT plan(4);

CREATE TABLE churn_models AS
SELECT row_number() OVER () AS n, arg_build(arg_generate_model(c, v, 12)) AS descr
FROM unnest(ARRAY['vase', 'cup', 'torus', 'chair', 'human', 'fourleg']) c, generate_series(0, 3) v;
CREATE TABLE churn (id bigserial PRIMARY KEY, n bigint, descr arg);
INSERT INTO churn (n, descr) SELECT n, descr FROM churn_models, generate_series(1, 50);
CREATE INDEX churn_descr ON churn USING arg_ivf (descr);
SELECT pg_relation_size('churn_descr') AS fresh_bytes \gset

-- Two rounds: about half the rows go (by a hash of the id, so every run alike), VACUUM, then
-- rows of the same models come in until there are 1,200 again.
CREATE VIEW churn_refill AS
SELECT m.n, m.descr FROM generate_series(1, 1200 - (SELECT count(*) FROM churn)) i
JOIN churn_models m ON m.n = 1 + i % 24;
DELETE FROM churn WHERE hashint8(id) % 2 = 0;
VACUUM churn;
INSERT INTO churn (n, descr) SELECT n, descr FROM churn_refill;
DELETE FROM churn WHERE hashint8(id + 1) % 2 = 0;
VACUUM churn;
INSERT INTO churn (n, descr) SELECT n, descr FROM churn_refill;
VACUUM churn;
SELECT pg_relation_size('churn_descr') AS churned_bytes \gset

SELECT is((SELECT count(*) FROM churn), 1200::bigint, 'after two rounds of churn the table has 1,200 rows');
SELECT is((SELECT entries FROM arg_index_check('churn_descr')), 1200::bigint,
          'arg_index_check: every row indexed once after the churn');
SELECT cmp_ok(:churned_bytes::numeric, '>=', :fresh_bytes::numeric * 0.99,
              'the churned index did not shrink below its first build (the rows are as many)');
REINDEX INDEX churn_descr;
SELECT cmp_ok(:churned_bytes::numeric / pg_relation_size('churn_descr'), '<=', 1.3,
              format('the churned index is within 1.3 times a fresh build (%s bytes against %s)',
                     :churned_bytes, pg_relation_size('churn_descr')));

SELECT * FROM finish();
DROP VIEW churn_refill;
DROP TABLE churn, churn_models;
