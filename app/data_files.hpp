// The scripts the tool runs (the plotting script, the benchmark peers): found beside an installed
// tool first, then in the source tree it was built from, so that neither a build folder nor an
// installed copy depends on the other.
#pragma once

#include <string>

namespace signorini::app {

/// The file `relative` (e.g. "plot_results.py", "peers/petsc_snesvi.py") looked for in order:
/// the environment variable `env_override` when it is set (its value is then used as is);
/// <folder of the running executable>/../share/signorini/<relative>;
/// <source tree>/<source_relative>. Returns the first that exists; throws InputError naming
/// every place tried and the environment variable otherwise.
std::string find_data_file(const std::string& relative, const std::string& source_relative,
                           const char* env_override);

/// The Python interpreter for the scripts: SIGNORINI_PYTHON when set (InputError, prefixed by
/// `purpose`, when it is not an executable file: "expected ... with `packages`"), else the Debian
/// interpreter /usr/bin/python3 (python3 on PATH may be a virtual environment or a pyenv shim
/// without the Debian packages), else python3 on PATH; "" when there is none.
std::string find_python(const std::string& purpose, const std::string& packages);

}  // namespace signorini::app
