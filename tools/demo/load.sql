-- Loads a catalogue of meshes into objects; run by tools/demo/run.sh.
-- stdin: the catalogue CSV (model_id,path,class,inventory_no,title,artist,period,material,
-- licence).
-- Variables: mode (sample|user), dir (base of relative paths), script (a scratch file),
-- every (a progress line per this many models).
-- The client reads the mesh files (\lo_import) and sends them: the server never reads the
-- project's files, it runs as another user.

SET client_min_messages = warning;
DROP TABLE IF EXISTS objects;
DROP EXTENSION IF EXISTS arg CASCADE;
CREATE EXTENSION arg CASCADE;

CREATE TABLE objects (
  id           integer PRIMARY KEY,      -- position in the catalogue
  model_id     text NOT NULL UNIQUE,
  inventory_no text,
  title        text NOT NULL,
  class        text,
  artist       text,
  period       text,
  material     text,
  licence      text,
  file         text NOT NULL,
  mesh         bytea NOT NULL,
  descr        arg GENERATED ALWAYS AS (arg_build(mesh)) STORED,
  thumbnail    bytea                     -- PNG for the browser, by tools/browser/thumbnails.py
);

CREATE TEMP TABLE catalogue (
  n serial, model_id text, path text, class text, inventory_no text, title text, artist text,
  period text, material text, licence text
);
\copy catalogue (model_id, path, class, inventory_no, title, artist, period, material, licence) FROM pstdin WITH (FORMAT csv, HEADER true)

SELECT count(*) AS total FROM catalogue \gset

-- One block per model: import the file client-side, insert it (arg_build runs in the generated
-- column), drop the large object. User models that fail to build are skipped with their error.
\pset tuples_only on
\pset format unaligned
\o :script
SELECT format(E'\\lo_import %s\n'
              '\\set lo :LASTOID\n'
              'INSERT INTO objects (id, model_id, inventory_no, title, class, artist, period, material, licence, file, mesh)\n'
              '  SELECT n, model_id, inventory_no, title, class, artist, period, material, licence, %L, lo_get(:lo)\n'
              '  FROM catalogue WHERE n = %s;\n'
              '%s'
              'SELECT lo_unlink(:lo) \\g /dev/null\n'
              '%s',
              -- psql meta-command quoting: backslashes and quotes doubled inside single quotes
              '''' || replace(replace(file, E'\\', E'\\\\'), '''', '''''') || '''',
              file_name, n,
              CASE WHEN :'mode' = 'user' THEN
                format(E'\\if :ERROR\n\\echo %s\n\\endif\n',
                       '''  skipped ' || replace(replace(file_name, E'\\', E'\\\\'), '''', '''''')
                       || ':'' :LAST_ERROR_MESSAGE')
              ELSE '' END,
              CASE WHEN n % :every = 0 OR n = :total THEN
                format(E'\\echo ''  %s/%s models done''\n', n, :total)
              ELSE '' END)
FROM (SELECT n,
             CASE WHEN path LIKE '/%' THEN path ELSE :'dir' || '/' || path END AS file,
             regexp_replace(path, '^.*/', '') AS file_name
      FROM catalogue) AS c
ORDER BY n;
\o
\pset tuples_only off
\pset format aligned

-- A user's file that does not build is reported and skipped; the sample must load whole.
SELECT :'mode' = 'user' AS skip_failures \gset
\if :skip_failures
\set ON_ERROR_STOP 0
\endif
\i :script
\set ON_ERROR_STOP 1

SELECT count(*) AS loaded FROM objects \gset
\echo 'demo:' :loaded 'of' :total 'models loaded'
