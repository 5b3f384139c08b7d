-- docs/REFERENCE.md documents every object of the extension (found through pg_depend, so a new
-- type, function, operator, operator class or family, or cast fails this file until it is
-- documented), every setting the module registers, and every SQLSTATE that extension/*.cpp
-- (ERRCODE_ names, turned into codes with PostgreSQL's own errcodes.h) and the install script's
-- PL/pgSQL raise. An object counts as documented when, in its section of the reference (the
-- "## " heading above it), a heading line or the first cell of a table row holds it as a `code`
-- span; white space does not matter. psql reads the three files from the repository's root,
-- where tests/run_all.sh runs pg_prove.
\set reference `cat docs/REFERENCE.md`
\set sources `cat extension/*.cpp`
\set errcodes `cat "$(${PG_CONFIG:-/usr/lib/postgresql/15/bin/pg_config} --includedir-server)/utils/errcodes.h"`
BEGIN;
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
SELECT plan(17);

CREATE TEMP TABLE files AS
SELECT :'reference'::text AS reference, :'sources'::text AS sources, :'errcodes'::text AS errcodes;
-- Calling a function loads the module, which registers the settings.
CREATE TEMP TABLE loaded AS SELECT arg_version();

-- Every SQLSTATE of errcodes.h by its macro name.
CREATE TEMP TABLE errcode_macros AS
SELECT m[1] AS name, m[2] || m[3] || m[4] || m[5] || m[6] AS code
FROM files, regexp_matches(errcodes, '#define\s+(ERRCODE_\w+)\s+MAKE_SQLSTATE\(''(.)'',\s*''(.)'',\s*'
                                     '''(.)'',\s*''(.)'',\s*''(.)''\)', 'g') m;
CREATE TEMP TABLE c_errcodes AS
SELECT DISTINCT m[1] AS name FROM files, regexp_matches(sources, '\m(ERRCODE_[A-Z0-9_]+)', 'g') m;

-- The SQLSTATE that PL/pgSQL gives a condition name.
CREATE FUNCTION pg_temp.sqlstate_of(condition text) RETURNS text LANGUAGE plpgsql AS $$
BEGIN
  RAISE EXCEPTION USING ERRCODE = condition;
EXCEPTION WHEN OTHERS THEN
  RETURN SQLSTATE;
END $$;

-- What the reference must document: the section it belongs in, the form it is written in (as a
-- code span) and what it is, for messages.
CREATE TEMP TABLE required AS
SELECT CASE d.classid
         WHEN 'pg_type'::regclass THEN 'Types'
         WHEN 'pg_proc'::regclass THEN 'Functions'
         WHEN 'pg_operator'::regclass THEN 'Operators'
         WHEN 'pg_opclass'::regclass THEN 'Operator classes and families'
         WHEN 'pg_opfamily'::regclass THEN 'Operator classes and families'
         WHEN 'pg_cast'::regclass THEN 'Casts'
         ELSE 'Other objects' END AS section,
       CASE d.classid
         WHEN 'pg_type'::regclass THEN format_type(d.objid, NULL)
         WHEN 'pg_proc'::regclass THEN d.objid::regprocedure::text
         WHEN 'pg_operator'::regclass THEN
           (SELECT format('%s %s %s', format_type(oprleft, NULL), oprname, format_type(oprright, NULL))
            FROM pg_operator WHERE oid = d.objid)
         WHEN 'pg_opclass'::regclass THEN
           (SELECT format('%s USING %s', opcname, amname)
            FROM pg_opclass JOIN pg_am ON pg_am.oid = opcmethod WHERE pg_opclass.oid = d.objid)
         WHEN 'pg_opfamily'::regclass THEN
           (SELECT format('%s USING %s', opfname, amname)
            FROM pg_opfamily JOIN pg_am ON pg_am.oid = opfmethod WHERE pg_opfamily.oid = d.objid)
         WHEN 'pg_cast'::regclass THEN
           (SELECT format('CAST (%s AS %s)', format_type(castsource, NULL), format_type(casttarget, NULL))
            FROM pg_cast WHERE oid = d.objid)
         ELSE pg_describe_object(d.classid, d.objid, d.objsubid) END AS form,
       pg_describe_object(d.classid, d.objid, d.objsubid) AS what
FROM pg_depend d JOIN pg_extension e ON e.oid = d.refobjid
WHERE d.refclassid = 'pg_extension'::regclass AND d.deptype = 'e' AND e.extname = 'arg'
  -- A type's array type comes with it (PostgreSQL 17 makes it a member of the extension too).
  AND NOT EXISTS (SELECT FROM pg_type t WHERE d.classid = 'pg_type'::regclass AND t.oid = d.objid
                    AND t.typcategory = 'A' AND t.typelem <> 0)
UNION ALL
SELECT 'Settings', name, 'setting ' || name FROM pg_settings WHERE name LIKE 'arg.%'
UNION ALL
SELECT 'SQLSTATEs', m.code, 'SQLSTATE ' || m.code || ' (' || c.name || ', extension/*.cpp)'
FROM c_errcodes c JOIN errcode_macros m USING (name)
UNION ALL
SELECT DISTINCT 'SQLSTATEs', pg_temp.sqlstate_of(m[1]),
       'SQLSTATE ' || pg_temp.sqlstate_of(m[1]) || ' (' || m[1] || ', ' || p.proname || ')'
FROM pg_depend d JOIN pg_extension e ON e.oid = d.refobjid
     JOIN pg_proc p ON p.oid = d.objid AND d.classid = 'pg_proc'::regclass
     JOIN pg_language l ON l.oid = p.prolang AND l.lanname = 'plpgsql',
     regexp_matches(p.prosrc, 'ERRCODE\s*=\s*''(\w+)''', 'g') m
WHERE d.deptype = 'e' AND e.extname = 'arg';

-- The entries of a reference text: each heading line and the first cell of each table row, with
-- the "## " section it is in.
CREATE FUNCTION pg_temp.entries(doc text) RETURNS TABLE (section text, entry text)
LANGUAGE sql IMMUTABLE AS $$
  WITH lines AS (
    SELECT n, line FROM regexp_split_to_table(doc, E'\n') WITH ORDINALITY AS l(line, n)),
  placed AS (
    SELECT n, line, max(n) FILTER (WHERE line ~ '^## ') OVER (ORDER BY n) AS heading FROM lines)
  SELECT regexp_replace(h.line, '^##\s+', ''),
         CASE WHEN p.line ~ '^#+ ' THEN p.line ELSE split_part(p.line, '|', 2) END
  FROM placed p JOIN lines h ON h.n = p.heading
  WHERE p.line ~ '^#+ ' OR p.line ~ '^\|'
$$;

-- What `doc` does not document of `required`.
CREATE FUNCTION pg_temp.undocumented(doc text) RETURNS TABLE (section text, what text)
LANGUAGE sql AS $$
  SELECT r.section, r.what FROM required r
  WHERE NOT EXISTS (
    SELECT FROM pg_temp.entries(doc) e
    WHERE e.section = r.section
      AND strpos(regexp_replace(e.entry, '\s', '', 'g'), '`' || regexp_replace(r.form, '\s', '', 'g') || '`') > 0)
  ORDER BY r.what
$$;

CREATE TEMP TABLE missing AS SELECT * FROM pg_temp.undocumented((SELECT reference FROM files));

-- The sources were read, and the lists built from them are not empty by mistake.
SELECT cmp_ok((SELECT length(reference) FROM files), '>', 10000, 'docs/REFERENCE.md was read');
SELECT cmp_ok((SELECT count(*) FROM errcode_macros), '>', 200::bigint,
              'the SQLSTATEs of PostgreSQL''s errcodes.h were read');
SELECT is(ARRAY(SELECT name FROM c_errcodes WHERE name NOT IN (SELECT name FROM errcode_macros) ORDER BY name),
          '{}'::text[], 'every ERRCODE_ name of extension/*.cpp is a SQLSTATE of errcodes.h');
SELECT ok((SELECT count(*) FILTER (WHERE section = 'Types') >= 2
              AND count(*) FILTER (WHERE section = 'Functions') >= 30
              AND count(*) FILTER (WHERE section = 'Operators') >= 7
              AND count(*) FILTER (WHERE section = 'Operator classes and families') >= 4
              AND count(*) FILTER (WHERE section = 'Settings') >= 6
              AND count(*) FILTER (WHERE section = 'SQLSTATEs') >= 10 FROM required),
          'the catalogue and the sources give the extension''s objects, settings and SQLSTATEs');

-- Everything is documented.
SELECT is(ARRAY(SELECT what FROM missing WHERE section = s), '{}'::text[],
          'docs/REFERENCE.md, section "' || s || '", documents every one the extension has')
FROM unnest(ARRAY['Types', 'Functions', 'Operators', 'Operator classes and families', 'Casts',
                  'Other objects', 'Settings', 'SQLSTATEs']) s;

-- And documents nothing the extension does not have: each signature of "Functions" is a
-- function of the extension, each arg.* name of "Settings" a setting.
SELECT is(ARRAY(SELECT span FROM pg_temp.entries((SELECT reference FROM files)) e,
                     regexp_matches(e.entry, '`(\w+\([^`]*\))`', 'g') m, LATERAL (SELECT m[1] AS span) s
                WHERE e.section = 'Functions'
                  AND NOT EXISTS (SELECT FROM required r WHERE r.section = 'Functions'
                                    AND r.form = to_regprocedure(span)::text)
                ORDER BY span),
          '{}'::text[], 'every function signature of docs/REFERENCE.md is a function of the extension');
SELECT is(ARRAY(SELECT m[1] FROM pg_temp.entries((SELECT reference FROM files)) e,
                     regexp_matches(e.entry, '`(arg\.\w+)`', 'g') m
                WHERE e.section = 'Settings' AND m[1] NOT IN (SELECT name FROM pg_settings)
                ORDER BY 1),
          '{}'::text[], 'every arg.* setting of docs/REFERENCE.md exists');

-- The checks can fail: the reference without one entry misses exactly that one.
SELECT is(ARRAY(SELECT what FROM pg_temp.undocumented(
                  regexp_replace((SELECT reference FROM files), '\n#[^\n]*`arg_svg\(arg, integer\)`[^\n]*', '')
                ) EXCEPT SELECT what FROM missing),
          ARRAY['function arg_svg(arg,integer)'],
          'without the heading of arg_svg, the reference misses arg_svg');
SELECT is(ARRAY(SELECT what FROM pg_temp.undocumented(
                  regexp_replace((SELECT reference FROM files), '\n\| `arg\.query_cache`[^\n]*', '')
                ) EXCEPT SELECT what FROM missing),
          ARRAY['setting arg.query_cache'],
          'without the row of arg.query_cache, the reference misses that setting');
SELECT is(ARRAY(SELECT what FROM pg_temp.undocumented(
                  regexp_replace((SELECT reference FROM files), '\n#[^\n]*`22P03`[^\n]*', '')
                ) EXCEPT SELECT what FROM missing),
          ARRAY['SQLSTATE 22P03 (ERRCODE_INVALID_BINARY_REPRESENTATION, extension/*.cpp)'],
          'without the heading of 22P03, the reference misses that SQLSTATE');

SELECT * FROM finish();
ROLLBACK;
