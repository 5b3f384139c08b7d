-- arg_functions: every function of the extension, on models from the generator.

CREATE EXTENSION arg;

-- arg_generate_model(class, variant, resolution) returns the OFF bytes of a closed mesh from
-- the project's deterministic generator: nine classes, any number of variants per class.
SELECT class,
       convert_from(substr(arg_generate_model(class, 0, 16), 1, 3), 'UTF8') AS format,
       arg_generate_model(class, 0, 16) = arg_generate_model(class, 0, 16) AS deterministic,
       arg_generate_model(class, 0, 16) <> arg_generate_model(class, 1, 16) AS variants_differ
FROM unnest(ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table', 'chair',
                  'octopus']) WITH ORDINALITY AS c(class, n)
ORDER BY n;

-- A catalogue of three variants of each class; the ARG is a generated column.
CREATE TABLE shapes (
  name  text PRIMARY KEY,
  class text NOT NULL,
  mesh  bytea NOT NULL,
  descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED
);
INSERT INTO shapes (name, class, mesh)
SELECT class || '_' || v, class, arg_generate_model(class, v, 32)
FROM unnest(ARRAY['vase', 'cup', 'amphora', 'torus', 'fourleg', 'human', 'table', 'chair',
                  'octopus']) AS class,
     generate_series(0, 2) AS v;

-- arg_info: what an ARG holds. The genus estimate counts the independent loops of the Reeb
-- graph: a cup's handle and a torus's hole make one each, an amphora's two handles two.
SELECT name, info->'levels' AS levels, info->'genus_estimate' AS genus,
       info->'components' AS components, info->'has_colour' AS colour, info->'open' AS open,
       (info->>'triangles')::int > 1000 AS many_triangles, info->>'options' AS options
FROM (SELECT name, arg_info(descr) AS info FROM shapes WHERE name LIKE '%\_0') s
ORDER BY name;
SELECT DISTINCT jsonb_object_keys(arg_info(descr)) AS key FROM shapes ORDER BY key;

-- arg_nodes: one row per node. Each level's areas sum to 1 / (levels + 1) (within the stored
-- areas' quantisation), every node but the root level's has a parent one level up, and the
-- counts agree with arg_info.
SELECT s.name, n.level, count(*) = (arg_info(s.descr)->'nodes_per_level'->>n.level)::int AS count_agrees,
       abs(sum(n.area) - 1.0 / 6) < 1e-4 AS area_is_a_sixth,
       bool_and(CASE WHEN n.level = 0 THEN n.parent IS NULL ELSE n.parent >= 0 END) AS parents,
       bool_and(n.mu_min <= n.mu_max) AS mu_ranges
FROM shapes s, arg_nodes(s.descr) n
WHERE s.name = 'cup_0'
GROUP BY s.name, n.level ORDER BY n.level;
SELECT count(*) AS nodes_without_parent_row
FROM shapes s, arg_nodes(s.descr) n
WHERE n.level > 0 AND NOT EXISTS (
  SELECT 1 FROM arg_nodes(s.descr) p WHERE p.level = n.level - 1 AND p.node = n.parent);

-- arg_sim: SIM in [0, 1], 0 for a model and itself, exactly symmetric, with every preset.
SELECT w AS weights,
       bool_and(arg_sim(a.descr, a.descr, w::arg_weights) = 0) AS self_is_zero,
       bool_and(arg_sim(a.descr, b.descr, w::arg_weights) = arg_sim(b.descr, a.descr, w::arg_weights)) AS symmetric,
       bool_and(arg_sim(a.descr, b.descr, w::arg_weights) BETWEEN 0 AND 1) AS in_unit_interval,
       bool_and(arg_sim(a.descr, b.descr, w::arg_weights) > 0 OR a.name = b.name) AS others_positive
FROM shapes a, shapes b, unnest(ARRAY['arg', 'mrg', 'shape', 'colour', 'arg level_ratio=0.6']) AS w
GROUP BY w ORDER BY w;

-- Weights change the score: the presets disagree on the same pair, and explicit values equal
-- to a preset give the same score as the preset.
SELECT count(DISTINCT arg_sim(a.descr, b.descr, w::arg_weights)) AS distinct_scores
FROM shapes a, shapes b, unnest(ARRAY['arg', 'mrg', 'shape', 'colour', 'arg level_ratio=0.6']) AS w
WHERE a.name = 'cup_0' AND b.name = 'vase_0';
-- level_ratio weighs the levels: at 0 the graph's SIM is the coarsest level's alone, where two
-- cups differ less than in their details; 1 is the default.
SELECT arg_sim(a.descr, b.descr, 'graph level_ratio=0') < arg_sim(a.descr, b.descr, 'graph') AS coarse_alike,
       arg_sim(a.descr, b.descr, 'level_ratio=1') = arg_sim(a.descr, b.descr) AS one_is_default
FROM shapes a, shapes b WHERE a.name = 'cup_0' AND b.name = 'cup_1';
SELECT arg_sim(a.descr, b.descr, 'arg') = arg_sim(a.descr, b.descr) AS default_is_arg,
       arg_sim(a.descr, b.descr, 'arg'::arg_weights::text::arg_weights) = arg_sim(a.descr, b.descr) AS explicit_equals_preset
FROM shapes a, shapes b WHERE a.name = 'cup_0' AND b.name = 'vase_0';

-- a <~> b is arg_sim(a, b) with the default weights: the two rank a table in the same order.
SELECT bool_and(a.descr <~> b.descr = arg_sim(a.descr, b.descr)) AS operator_is_arg_sim
FROM shapes a, shapes b;
SELECT q.name AS query,
       (SELECT array_agg(s.name ORDER BY s.descr <~> q.descr, s.name) FROM shapes s) =
       (SELECT array_agg(s.name ORDER BY arg_sim(s.descr, q.descr), s.name) FROM shapes s) AS same_order
FROM shapes q ORDER BY q.name;

-- The ranking query: the closest model to a query is itself (SIM 0); the next ones follow.
SELECT s.name, s.class, s.descr <~> q.descr = 0 AS same_shape
FROM shapes s, shapes q
WHERE q.name = 'torus_1'
ORDER BY s.descr <~> q.descr, s.name LIMIT 3;

-- arg_matches: the node pairs behind a score, level by level. A model matches itself node for
-- node.
SELECT level, count(*) AS pairs, bool_and(a_node = b_node) AS node_to_itself
FROM shapes s, arg_matches(s.descr, s.descr) m
WHERE s.name = 'cup_0' GROUP BY level ORDER BY level;
SELECT count(*) > 0 AS some_pairs,
       bool_and(sim >= 0 AND loss >= 0) AS non_negative,
       count(DISTINCT (level, match_group)) <= count(*) AS groups
FROM shapes a, shapes b, arg_matches(a.descr, b.descr, 'mrg') m
WHERE a.name = 'cup_0' AND b.name = 'cup_1';

-- arg_part_match: the parts of each candidate that match one node of a query (here node 0 of
-- level 2 of cup_0), best first; joined laterally over the table. The query's own node matches
-- itself with a score of 0.
SELECT s.name, p.candidate_level AS level, p.candidate_node AS node, round(p.score::numeric, 6) AS score
FROM shapes s, arg_part_match((SELECT descr FROM shapes WHERE name = 'cup_0'), 2, 0, s.descr) p
WHERE s.name = 'cup_0'
ORDER BY p.score, p.candidate_level, p.candidate_node LIMIT 1;
SELECT bool_and(score >= 0) AS scores_non_negative,
       bool_and(candidate_level BETWEEN 1 AND 3) AS neighbouring_levels,
       count(DISTINCT s.name) > 1 AS several_models
FROM shapes s, arg_part_match((SELECT descr FROM shapes WHERE name = 'cup_0'), 2, 0, s.descr);
-- Rows come out best first.
SELECT bool_and(ok) AS ordered FROM (
  SELECT p.score >= lag(p.score, 1, 0::float8) OVER (PARTITION BY s.name ORDER BY ord) AS ok
  FROM shapes s,
       arg_part_match((SELECT descr FROM shapes WHERE name = 'cup_0'), 2, 0, s.descr)
         WITH ORDINALITY AS p(candidate_level, candidate_node, score, ord)) o;
-- Its default weights are the `part` preset (0.2.0's feature weights), not `arg`'s.
SELECT strpos(pg_get_function_arguments('arg_part_match'::regproc),
              format('DEFAULT %L::arg_weights', 'part'::arg_weights)) > 0 AS default_part,
       (SELECT array_agg(p ORDER BY s.name, p) FROM shapes s,
          arg_part_match((SELECT descr FROM shapes WHERE name = 'cup_0'), 2, 0, s.descr) p)
       = (SELECT array_agg(p ORDER BY s.name, p) FROM shapes s,
          arg_part_match((SELECT descr FROM shapes WHERE name = 'cup_0'), 2, 0, s.descr, 'part') p)
         AS same_as_part;

-- arg_svg: one level of the graph as a self-contained SVG picture, one circle per node.
SELECT name, left(svg, 4) AS starts,
       (length(svg) - length(replace(svg, '<circle', ''))) / length('<circle') =
         (arg_info(descr)->'nodes_per_level'->>2)::int AS one_circle_per_node,
       svg NOT LIKE '%<script%' AND svg NOT LIKE '%href%' AS self_contained
FROM (SELECT name, descr, arg_svg(descr) AS svg FROM shapes WHERE name = 'octopus_0') s;
SELECT arg_svg(descr, 0) <> arg_svg(descr, 4) AS levels_differ FROM shapes WHERE name = 'cup_0';

-- arg_build's options change the result: a coarser graph, another mu.
SELECT options, info->'levels' AS levels, info->>'options' AS stored_options
FROM (SELECT options, arg_info(arg_build(mesh, options)) AS info
      FROM shapes, unnest(ARRAY['', 'levels=3', 'levels=4 mu=height', 'mu=centroid base_points=64']) AS options
      WHERE name = 'cup_0') s;
-- threads= never changes the result.
SELECT arg_build(mesh, 'threads=2') = descr AS threads_do_not_matter FROM shapes WHERE name = 'cup_0';

-- arg_build(mesh, texture, options): an OBJ whose colour comes from a separate image. The same
-- octahedron with two 2 x 2 PNG textures (red above blue, and plain green) has the same shape
-- but other colour histograms: the shape preset finds them (almost) identical, the colour
-- preset does not. Without a texture the ARG has no colour at all. (A literal texture needs
-- ::bytea: an untyped literal in second place is read as the options of arg_build(mesh, options).)
CREATE TABLE textured AS
SELECT arg_build(obj, '\x89504e470d0a1a0a0000000d4948445200000002000000020802000000fdd49a73000000114944415478da6338212707440c60f204001c7e0411f033d5060000000049454e44ae426082'::bytea) AS red_blue,
       arg_build(obj, '\x89504e470d0a1a0a0000000d4948445200000002000000020802000000fdd49a73000000104944415478da63903b2107440c100a001c7e04117d192f970000000049454e44ae426082'::bytea) AS green,
       arg_build(obj) AS plain
FROM (SELECT convert_to('v 1 0 0
v -1 0 0
v 0 1 0
v 0 -1 0
v 0 0 1
v 0 0 -1
vt 0.5 0.5
vt 0.5 0.5
vt 0.5 0.5
vt 0.5 0.5
vt 0.5 0.9
vt 0.5 0.1
f 1/1 3/3 5/5
f 3/3 2/2 5/5
f 2/2 4/4 5/5
f 4/4 1/1 5/5
f 3/3 1/1 6/6
f 2/2 3/3 6/6
f 4/4 2/2 6/6
f 1/1 4/4 6/6
', 'UTF8') AS obj) o;
SELECT arg_info(red_blue)->'has_colour' AS red_blue_colour,
       arg_info(plain)->'has_colour' AS plain_colour,
       arg_sim(red_blue, green, 'shape') < 1e-6 AS same_shape,
       arg_sim(red_blue, green, 'colour') > 0.01 AS other_colour
FROM textured;

SELECT arg_version();

DROP TABLE shapes, textured;
DROP EXTENSION arg;
