// Fuzzing (issue 17, item 7), the small fixed-seed version: 80 mutations of
// the files of prm/ (tools/fuzz-prm.py, seed 17: numbers to 0, negative,
// huge, nan, inf, text; lists shortened and lengthened; lines dropped,
// duplicated, misspelt; subsections unbalanced; binary junk; truncation)
// read by `vesicle-iga --check`. Every case must be accepted or refused
// with exit code 1 and one message; a crash (signal, abort, uncaught
// exception), a hang (60 s) or an accepted non-finite value is a finding
// and is printed. The large runs, with a few steps of the cheap studies,
// are in doc/reliability.md.
//
// Expected output checked by hand: no findings.

#include <iostream>

#include "subprocess.h"

int
main()
{
  std::ofstream       out("output");
  const ProcessResult r
    = run_process(std::string("env -C ") + VESICLE_IGA_SOURCE_DIR
                    + " python3 tools/fuzz-prm.py --cases 80 --seed 17"
                      " --timeout 60 --binary " VESICLE_IGA_BINARY,
                  1200);
  std::istringstream lines(r.output);
  unsigned int       findings = 0;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("CRASH", 0) == 0 || line.rfind("HANG", 0) == 0
        || line.rfind("INVALID", 0) == 0)
      {
        out << line << '\n';
        ++findings;
      }
  out << "cases run: " << contains(r.output, "80 cases from")
      << "\nfindings: " << findings << "\nexit code " << r.exit_code << '\n';
}
