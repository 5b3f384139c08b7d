-- The demo's ranking query: the models ordered by shape similarity to one of them.
-- Variables: mode (sample|user), query (a model_id, or empty for the first), rows (to print).

SELECT count(*) AS models, least(:rows, count(*)) AS shown FROM museum_models \gset
SELECT id AS query_id, model_id AS query_model, title AS query_title,
       coalesce(class, file) AS query_kind
FROM museum_models
WHERE model_id = :'query' OR (:'query' = '' AND id = (SELECT min(id) FROM museum_models)) \gset

\echo
\echo 'The' :shown 'of' :models 'models most like' :query_model '"':query_title'" (':query_kind'), by shape alone.'
\echo 'sim is SIM(query, model): 0 for the same shape, up to 1. The query:'
\echo '  SELECT ... FROM museum_models m, museum_models q WHERE q.model_id =' :'query_model' 'ORDER BY m.descr <~> q.descr'
\echo

SELECT :'mode' = 'user' AS user_models \gset
\if :user_models
SELECT rank() OVER (ORDER BY m.descr <~> q.descr) AS rank,
       m.model_id, m.title, m.file,
       round((m.descr <~> q.descr)::numeric, 4) AS sim
FROM museum_models m, museum_models q
WHERE q.id = :query_id
ORDER BY m.descr <~> q.descr, m.id
LIMIT :rows;
\else
SELECT rank() OVER (ORDER BY m.descr <~> q.descr) AS rank,
       m.model_id, m.inventory_no, m.title, m.class, m.artist, m.period, m.material,
       round((m.descr <~> q.descr)::numeric, 4) AS sim
FROM museum_models m, museum_models q
WHERE q.id = :query_id
ORDER BY m.descr <~> q.descr, m.id
LIMIT :rows;
\endif
