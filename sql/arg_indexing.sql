-- arg_indexing: a museum catalogue keeps the ARG of each object's mesh up to date on insert and
-- update, with a generated column or with the trigger function arg_index_trigger().

CREATE EXTENSION arg;

-- 1. A generated column: the simplest way. The ARG is built when a row is inserted and rebuilt
--    when its mesh changes; PostgreSQL never lets it disagree with the mesh.
CREATE TABLE objects (
  id           serial PRIMARY KEY,
  inventory_no text UNIQUE NOT NULL,
  title        text NOT NULL,
  artist       text,
  period       text,
  material     text,
  mesh         bytea,
  texture      bytea,
  descr        arg GENERATED ALWAYS AS (arg_build(mesh)) STORED
);

INSERT INTO objects (inventory_no, title, artist, period, material, mesh) VALUES
  ('1911.23', 'Kylix', 'Painter of Berlin', 'Classical', 'terracotta', arg_generate_model('cup', 0, 24)),
  ('1911.24', 'Amphora', NULL, 'Archaic', 'terracotta', arg_generate_model('amphora', 0, 24)),
  ('1956.02', 'Standing youth', NULL, 'Archaic', 'marble', arg_generate_model('human', 0, 24)),
  ('2001.17', 'Ring', NULL, 'Roman', 'gold', arg_generate_model('torus', 0, 24)),
  ('2001.18', 'Record without a scan yet', NULL, 'Roman', 'bronze', NULL);

SELECT inventory_no, descr IS NOT NULL AS indexed, descr = arg_build(mesh) AS up_to_date
FROM objects ORDER BY inventory_no;

-- Changing the mesh rebuilds the ARG; scanning the missing object fills it in.
UPDATE objects SET mesh = arg_generate_model('cup', 1, 24) WHERE inventory_no = '1911.23';
UPDATE objects SET mesh = arg_generate_model('fourleg', 0, 24) WHERE inventory_no = '2001.18';
SELECT inventory_no, descr = arg_build(arg_generate_model(m.class, m.variant, 24)) AS rebuilt
FROM objects JOIN (VALUES ('1911.23', 'cup', 1), ('2001.18', 'fourleg', 0)) AS m(no, class, variant)
  ON inventory_no = m.no
ORDER BY inventory_no;

-- A transaction that is rolled back leaves nothing behind.
BEGIN;
INSERT INTO objects (inventory_no, title, mesh) VALUES ('2024.01', 'Vase', arg_generate_model('vase', 0, 24));
UPDATE objects SET mesh = arg_generate_model('table', 0, 24) WHERE inventory_no = '1911.24';
SELECT count(*) AS objects_inside FROM objects;
ROLLBACK;
SELECT count(*) AS objects_after, bool_and(descr = arg_build(mesh)) AS all_up_to_date FROM objects;

-- A mesh that cannot be read fails the whole statement: no row is half stored.
INSERT INTO objects (inventory_no, title, mesh) VALUES
  ('2024.02', 'Good vase', arg_generate_model('vase', 1, 24)),
  ('2024.03', 'Corrupt file', convert_to('OFF
3 1 0
0 0 0
1 0
', 'UTF8'));
SELECT count(*) AS objects_after_failed_insert FROM objects;

-- 2. The trigger: for a table whose ARG is built with a texture or with options, or where a
--    generated column does not fit. arg_index_trigger(mesh_column, arg_column [, texture_column
--    [, build_options]]) builds on INSERT, and on UPDATE only when the mesh or the texture
--    changed (or the ARG was set to NULL, which forces a rebuild): editing a title is cheap.
CREATE TABLE scans (
  id      serial PRIMARY KEY,
  title   text NOT NULL,
  mesh    bytea,
  texture bytea,
  descr   arg
);
CREATE TRIGGER scans_descr BEFORE INSERT OR UPDATE ON scans
  FOR EACH ROW EXECUTE FUNCTION arg_index_trigger('mesh', 'descr', 'texture', 'levels=4');

INSERT INTO scans (title, mesh) VALUES
  ('Octopus vase', arg_generate_model('octopus', 0, 24)),
  ('Chair', arg_generate_model('chair', 0, 24)),
  ('Not scanned', NULL);
SELECT title, descr IS NOT NULL AS indexed, arg_info(descr)->'levels' AS levels,
       descr = arg_build(mesh, 'levels=4') AS up_to_date
FROM scans ORDER BY id;

-- An update of the metadata does not build: it goes through even under a size cap that the
-- mesh is over. An update of the mesh builds, and fails under that cap.
SET arg.max_input_size = '1kB';
UPDATE scans SET title = 'Octopus vase (restored)' WHERE title = 'Octopus vase';
UPDATE scans SET mesh = arg_generate_model('octopus', 1, 24) WHERE title = 'Chair';
RESET arg.max_input_size;
UPDATE scans SET mesh = arg_generate_model('octopus', 1, 24) WHERE title = 'Chair';
UPDATE scans SET mesh = arg_generate_model('vase', 2, 24) WHERE title = 'Not scanned';
SELECT title, descr = arg_build(mesh, 'levels=4') AS up_to_date FROM scans ORDER BY id;

-- Setting the ARG to NULL rebuilds it; a mesh set to NULL clears it.
UPDATE scans SET descr = NULL WHERE title = 'Chair';
UPDATE scans SET mesh = NULL WHERE title = 'Not scanned';
SELECT title, descr IS NOT NULL AS indexed, descr = arg_build(mesh, 'levels=4') AS up_to_date
FROM scans ORDER BY id;

-- Rolled back, the trigger's work disappears with the rows.
BEGIN;
INSERT INTO scans (title, mesh) VALUES ('Cup', arg_generate_model('cup', 2, 24));
UPDATE scans SET mesh = arg_generate_model('human', 1, 24) WHERE title = 'Chair';
ROLLBACK;
SELECT count(*) AS scans_after, count(descr) AS indexed,
       bool_and(descr = arg_build(mesh, 'levels=4')) AS all_up_to_date FROM scans;

-- The trigger checks how it is used.
CREATE TABLE wrong (id int, mesh text, descr arg);
CREATE TRIGGER wrong_column BEFORE INSERT ON wrong
  FOR EACH ROW EXECUTE FUNCTION arg_index_trigger('no_such_column', 'descr');
INSERT INTO wrong VALUES (1, 'x', NULL);
DROP TRIGGER wrong_column ON wrong;
CREATE TRIGGER wrong_type BEFORE INSERT ON wrong
  FOR EACH ROW EXECUTE FUNCTION arg_index_trigger('mesh', 'descr');
INSERT INTO wrong VALUES (1, 'x', NULL);
DROP TRIGGER wrong_type ON wrong;
CREATE TRIGGER wrong_arguments BEFORE INSERT ON wrong
  FOR EACH ROW EXECUTE FUNCTION arg_index_trigger('mesh');
INSERT INTO wrong VALUES (1, 'x', NULL);
DROP TRIGGER wrong_arguments ON wrong;
CREATE TRIGGER wrong_timing AFTER INSERT ON wrong
  FOR EACH ROW EXECUTE FUNCTION arg_index_trigger('mesh', 'descr');
INSERT INTO wrong VALUES (1, 'x', NULL);
SELECT count(*) AS rows_in_wrong FROM wrong;

DROP TABLE objects, scans, wrong;
DROP EXTENSION arg;
