-- The demo's ranking query: the models ordered by shape similarity to one of them.
-- Variables: mode (sample|user), query (a model_id, or empty for the first), rows (to print).

SELECT count(*) AS models, least(:rows, count(*)) AS shown FROM objects \gset
SELECT id AS query_id, model_id AS query_model, title AS query_title,
       coalesce(class, file) AS query_kind
FROM objects
WHERE model_id = :'query' OR (:'query' = '' AND id = (SELECT min(id) FROM objects)) \gset

\echo
\echo 'The' :shown 'of' :models 'models most like' :query_model '"':query_title'" (':query_kind'), by shape alone.'
\echo 'sim is SIM(query, model): 0 for the same shape, up to 1. The query:'
\echo '  SELECT ... FROM objects m, objects q WHERE q.model_id =' :'query_model' 'ORDER BY m.descr <~> q.descr'
\echo

-- About 100 characters a row: the title cut to 32, the class, the period and SIM.
SELECT rank() OVER (ORDER BY m.descr <~> q.descr) AS rank,
       left(m.model_id, 24) AS model_id,
       CASE WHEN length(m.title) > 32 THEN left(m.title, 31) || '…' ELSE m.title END AS title,
       m.class, m.period,
       round((m.descr <~> q.descr)::numeric, 4) AS sim
FROM objects m, objects q
WHERE q.id = :query_id
ORDER BY m.descr <~> q.descr, m.id
LIMIT :rows;
