#!/usr/bin/env bash
# The pipeline's time by part from its provenance database (docs/benchmarks.md, "The schedule on
# 2 cores"): each recorded run's wall time, the runs grouped by what they made (their outputs'
# paths). Calibration trials (outputs .../trial-NN) are left out: the mw-calibrate run that
# started them holds their time. The sum is the tools' time, not the pipeline's wall time
# (runs overlap under make -j, and make and the scripts add their own).
#
#   bench/pipeline_parts.sh DB            (e.g. db/provenance-quick.sqlite)
set -euo pipefail
db=${1:?usage: bench/pipeline_parts.sh DB}
sqlite3 -batch -separator ' | ' "$db" "
with out as (
  select r.id, r.tool, r.wall_s, coalesce((select min(path) from files f where f.run_id = r.id and f.role = 'output'), '') as p
  from runs r where r.exit_status = 0),
parts as (
  select wall_s, case
    when p like '%/trial-%' then null
    when p like '%/concrete-cube/calibration%' then 'cube: calibration (step 6, its trials included)'
    when p like '%/concrete-cube/compression-paper-parameters%' then 'cube: compression with the paper''s parameters'
    when p like '%/concrete-cube/dem-%' then 'cube: DEM waves'
    when p like '%/concrete-cube/fem-early-%' then 'cube: FEM references, first 50 us'
    when p like '%/concrete-cube/fem-%' then 'cube: FEM references, whole record'
    when p like '%/concrete-cube/speed-%' and tool = 'mw-dem' then 'cube: speed against error (DEM runs)'
    when p like '%/concrete-cube/packing%' and tool = 'mw-pack' then 'cube: packing'
    when p like '%/steel-rod/%' then 'steel rod study'
    when p like '%/shock-concrete/%' then 'shock-concrete study'
    else 'lab steps, PCC, tables, report' end as part
  from out)
select part, runs, printf('%.1f', wall_s) from (
  select part, count(*) as runs, sum(wall_s) as wall_s, 0 as last from parts where part is not null group by part
  union all select 'all', count(*), sum(wall_s), 1 from parts where part is not null)
order by last, wall_s desc;"
