-- mesowave provenance database (SQLite, WAL mode).
-- One row per tool run; the files a run read and wrote, and the named metrics
-- it reported, hang off that row. The tools compile this file in and apply it
-- to a new database; `sqlite3 db/provenance.sqlite` reads it directly.

CREATE TABLE IF NOT EXISTS meta (
  key   TEXT PRIMARY KEY,
  value TEXT NOT NULL
);
INSERT OR IGNORE INTO meta (key, value) VALUES ('schema_version', '1');
INSERT OR IGNORE INTO meta (key, value) VALUES ('application', 'mesowave provenance');

CREATE TABLE IF NOT EXISTS runs (
  id            INTEGER PRIMARY KEY,
  tool          TEXT    NOT NULL,  -- mw-upv, mw-dem, ...
  version       TEXT    NOT NULL,  -- git describe of the last commit that changed the code it was built from (+ -dirty)
  binary_sha256 TEXT    NOT NULL,  -- SHA-256 of the executable that ran
  argv          TEXT    NOT NULL,  -- JSON array, as typed
  params        TEXT    NOT NULL,  -- JSON object: every option's final value, files included
  cwd           TEXT    NOT NULL,
  host          TEXT    NOT NULL,
  started_at    TEXT    NOT NULL,  -- ISO 8601, UTC, milliseconds
  ended_at      TEXT    NOT NULL,
  exit_status   INTEGER NOT NULL,  -- 0 success, 1 bad input, 2 internal failure, 128+N interrupted by signal N
  error         TEXT,              -- the one-line message of a failed run
  wall_s        REAL    NOT NULL,
  cpu_s         REAL    NOT NULL,  -- user + system time of the process
  peak_rss_kib  INTEGER NOT NULL   -- peak resident memory
);
CREATE INDEX IF NOT EXISTS runs_by_tool ON runs (tool, id);

CREATE TABLE IF NOT EXISTS files (
  run_id     INTEGER NOT NULL REFERENCES runs (id) ON DELETE CASCADE,
  role       TEXT    NOT NULL CHECK (role IN ('input', 'output')),
  path       TEXT    NOT NULL,     -- absolute and normalised
  size_bytes INTEGER NOT NULL,
  sha256     TEXT    NOT NULL,     -- content hash when the run read or wrote it
  PRIMARY KEY (run_id, role, path)
);
CREATE INDEX IF NOT EXISTS files_by_path ON files (path, role, run_id);
CREATE INDEX IF NOT EXISTS files_by_hash ON files (sha256);

CREATE TABLE IF NOT EXISTS metrics (
  run_id INTEGER NOT NULL REFERENCES runs (id) ON DELETE CASCADE,
  name   TEXT    NOT NULL,          -- E_d, pcc_mean, steps_per_s, ...
  value  REAL    NOT NULL,
  unit   TEXT    NOT NULL,          -- '' for dimensionless values
  PRIMARY KEY (run_id, name)
);
CREATE INDEX IF NOT EXISTS metrics_by_name ON metrics (name, run_id);
