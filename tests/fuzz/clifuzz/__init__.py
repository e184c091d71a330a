"""The seeded fuzzer of the `selfalign` command line, one concept per module; its entry point is
../fuzz_cli.py.

  vocabulary      the command line: subcommands, flags, kinds of values, config keys
  values          valid, edge and big values per flag; base command lines; samples variants
  contract        documented allowances (nulls, non-finite CSV cells, error line) and limits
  case            a case: argument units, files to create, inputs and outputs
  config_files    JSON / TOML rendering, recipes of big files
  mutate_flags    mutations of flags and their values
  mutate_inputs   mutations of config files and samples CSVs
  mutate_outputs  outputs colliding with inputs, folders, FIFOs, symbolic links
  corpus          the fixed cases (one per contract item and known defect class)
  generate        case i of a seed: corpus, or a random case
  folder          the case folder: create, snapshot, FIFO readers, read back
  runner          running cases: temporary folders, timeouts, limits, parallel jobs
  checks          checking one run: exit code, folder, error line
  content         checking an output's JSON / CSV content
  reproducer      a case as a shell command line
  shrink          a failing case reduced to a minimal one
  report          failures, minimal reproducers, counts
"""
