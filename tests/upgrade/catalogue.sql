-- The extension's catalogue as lines of text: every member object with what defines it (a
-- function's full definition with its volatility, strictness, parallel safety and cost; a type's
-- storage and support functions; an operator's function and estimators; an operator family's
-- members) and its comment. Two databases hold the same extension exactly when these are equal.
WITH member AS (
  SELECT d.classid, d.objid FROM pg_depend d JOIN pg_extension e ON e.oid = d.refobjid
  WHERE d.refclassid = 'pg_extension'::regclass AND d.deptype = 'e' AND e.extname = 'arg')
SELECT pg_describe_object(classid, objid, 0) || ' | ' ||
       coalesce(CASE classid
         WHEN 'pg_proc'::regclass THEN pg_get_functiondef(objid)
         WHEN 'pg_type'::regclass THEN
           (SELECT format('%s %s %s %s %s %s %s %s', typlen, typalign, typstorage, typinput,
                          typoutput, typreceive, typsend, typdefault)
            FROM pg_type WHERE oid = objid)
         WHEN 'pg_operator'::regclass THEN
           (SELECT format('%s %s %s %s %s %s %s', oprcode, oprcom::regoperator,
                          oprnegate::regoperator, oprrest, oprjoin, oprcanhash, oprcanmerge)
            FROM pg_operator WHERE oid = objid)
         WHEN 'pg_opclass'::regclass THEN
           (SELECT format('%s %s', opcdefault, opcintype::regtype) FROM pg_opclass WHERE oid = objid)
         WHEN 'pg_opfamily'::regclass THEN
           (SELECT string_agg(member, ', ' ORDER BY member) FROM (
              SELECT pg_describe_object('pg_amop'::regclass, oid, 0) AS member
              FROM pg_amop WHERE amopfamily = objid
              UNION ALL
              SELECT pg_describe_object('pg_amproc'::regclass, oid, 0)
              FROM pg_amproc WHERE amprocfamily = objid) m)
       END, '') || ' | ' || coalesce(obj_description(objid, classid::regclass::name), '')
FROM member ORDER BY 1;
