# arg: the PostgreSQL extension (a PGXS makefile) and the project's top-level targets.
#
#   make                     configure CMake once, build the core library and argtool, then the
#                            extension
#   make install             install the extension into PostgreSQL (PG_CONFIG's; 15 by default)
#                            and argtool into $(BINDIR) (as root, or it uses sudo)
#   make test                install missing packages, build everything, run every test suite
#   make demo [MODELS=DIR]   install only what the demo needs, build only what it runs, then rank a
#                            sample catalogue (or DIR's meshes, with DIR/catalogue.csv) in a
#                            throwaway cluster and start the catalogue browser beside it
#   make demo-stop           stop the demo's browser and cluster
#   make deb                 Debian packages postgresql-<major>-arg and argtool (tools/deb) in
#                            $(BUILD_DIR)/deb, for the PostgreSQL of PG_CONFIG
#   make installcheck        pg_regress (sql/, expected/) against the server in PGHOST/PGPORT
#   make distclean           stop the clusters and remove the build tree

BUILD_DIR ?= build
CMAKE ?= cmake
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release $(if $(CI),-DARG_WERROR=ON)
# Where `make install` puts argtool (the Debian package: /usr/bin), and its plug-ins beside it
# (lib/argtool: argtool looks there).
BINDIR ?= /usr/local/bin
ARGTOOL_LIBDIR = $(patsubst %/bin,%/lib/argtool,$(BINDIR))
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# The method library, and the two layers the extension's arg_generate and arg_inspect need (the
# model generator, the graph's SVG); never the evaluation library (core/libraries.cmake).
CORE_LIB := $(BUILD_DIR)/libargmethod.a
CORE_LIBS := $(BUILD_DIR)/libargrender.a $(BUILD_DIR)/libarggen.a $(CORE_LIB)
PG_CONFIG ?= $(firstword $(wildcard /usr/lib/postgresql/15/bin/pg_config) $(shell command -v pg_config 2>/dev/null))
SUDO := $(if $(filter 0,$(shell id -u)),,sudo)
export BUILD_DIR

# The extension ------------------------------------------------------------------------------

EXTVERSION := $(shell sed -n "s/^default_version *= *'\(.*\)'/\1/p" extension/arg.control)
MODULE_big = arg
OBJS = $(patsubst %.cpp,%.o,$(wildcard extension/*.cpp))
# The control file lives in extension/, so install it as DATA rather than through EXTENSION.
MODULEDIR = extension
DATA = extension/arg.control $(wildcard extension/arg--*.sql)
PGFILEDESC = "arg - Augmented Reeb Graphs for 3D shape search"

REGRESS = $(sort $(basename $(notdir $(wildcard sql/*.sql))))
REGRESS_OPTS = --outputdir=$(BUILD_DIR)/regress --load-extension=cube

PG_CPPFLAGS = -Icore -I/usr/include/eigen3 -DARG_VERSION='"$(EXTVERSION)"' -D_USE_MATH_DEFINES
PG_CXXFLAGS = -std=c++17 -Wextra -Wno-unused-parameter -Wno-missing-field-initializers \
              $(if $(CI),-Werror)
# OpenImageIO is not linked: arg_image.so (built by CMake) is loaded on the first texture.
# OpenMesh: the OBJ reader.
SHLIB_LINK = $(CORE_LIBS) -lOpenMeshCore -lz -pthread -lstdc++
IMAGE_LIB = $(BUILD_DIR)/arg_image$(DLSUFFIX)
# OpenVDB is not linked either: arg_vdb.so is loaded on the first build that makes a proxy.
VDB_LIB = $(BUILD_DIR)/arg_vdb$(DLSUFFIX)

# PGXS's LLVM bitcode rule ignores PG_CXXFLAGS (so no -std=c++17) and JIT inlining gains nothing
# here: build without bitcode. Track header dependencies so core header changes rebuild the glue.
override with_llvm := no
override autodepend := yes

# The PostgreSQL versions whose server API extension/ is written and tested against: 15 and 17
# (make test runs the SQL suites on both), 16 between them (compiled, not tested).
SUPPORTED_PG := 15 16 17
ifneq ($(PG_CONFIG),)
PG_MAJOR := $(shell $(PG_CONFIG) --version | sed -E 's/^PostgreSQL ([0-9]+).*/\1/')
ifeq ($(filter $(SUPPORTED_PG),$(PG_MAJOR)),)
ifeq ($(filter deps deps-demo distclean demo-stop,$(MAKECMDGOALS)),)
$(error arg supports PostgreSQL $(SUPPORTED_PG); $(PG_CONFIG) is PostgreSQL $(PG_MAJOR): set PG_CONFIG to the pg_config of a supported server)
endif
endif
PGXS := $(shell $(PG_CONFIG) --pgxs)
include $(PGXS)
else
all install installcheck:
	@echo "pg_config (PostgreSQL 15 or 17) not found: run 'make deps' (or 'make test'/'make demo') first" >&2
	@exit 1
endif

# The core, built by CMake -------------------------------------------------------------------

$(BUILD_DIR)/CMakeCache.txt:
	$(CMAKE) -S . -B $(BUILD_DIR) $(CMAKE_FLAGS)

# ARG_NO_CMAKE=1 (used for the sudo install step) takes the library as it is.
ifneq ($(ARG_NO_CMAKE),1)
$(CORE_LIB): FORCE | $(BUILD_DIR)/CMakeCache.txt
	$(CMAKE) --build $(BUILD_DIR) --target argmethod arggen argrender argimage argvdb argtool -j $(JOBS)
endif
$(filter-out $(CORE_LIB),$(CORE_LIBS)): $(CORE_LIB) ;

arg$(DLSUFFIX): $(CORE_LIBS)

install: install-plugins
.PHONY: install-plugins
install-plugins:
	$(INSTALL_SHLIB) '$(IMAGE_LIB)' '$(DESTDIR)$(pkglibdir)/arg_image$(DLSUFFIX)'
	$(INSTALL_SHLIB) '$(VDB_LIB)' '$(DESTDIR)$(pkglibdir)/arg_vdb$(DLSUFFIX)'
	$(MKDIR_P) '$(DESTDIR)$(BINDIR)' '$(DESTDIR)$(ARGTOOL_LIBDIR)'
	$(INSTALL_PROGRAM) '$(BUILD_DIR)/argtool' '$(DESTDIR)$(BINDIR)/argtool'
	$(INSTALL_SHLIB) '$(IMAGE_LIB)' '$(DESTDIR)$(ARGTOOL_LIBDIR)/arg_image$(DLSUFFIX)'
	$(INSTALL_SHLIB) '$(VDB_LIB)' '$(DESTDIR)$(ARGTOOL_LIBDIR)/arg_vdb$(DLSUFFIX)'

.PHONY: FORCE
FORCE:

# Top-level targets --------------------------------------------------------------------------

.PHONY: deps deps-demo cmake-all build test fuzz cancel-check demo demo-stop deb distclean

deps:
	tools/pg/install_deps.sh

deps-demo:
	tools/pg/install_deps.sh --demo

# Every CMake target (core, argtool, unit tests, benchmarks), then the extension. The tests and
# benchmarks are switched on here, should a demo have configured the tree without them.
cmake-all: | $(BUILD_DIR)/CMakeCache.txt
	$(CMAKE) -S . -B $(BUILD_DIR) -DARG_BUILD_TESTS=ON -DARG_BUILD_BENCH=ON >/dev/null
	$(CMAKE) --build $(BUILD_DIR) -j $(JOBS)

build: cmake-all
	$(MAKE) --no-print-directory all

# Each step is a new make so that PGXS is read after `deps` has installed PostgreSQL.
test: deps
	tests/versions/head_start.sh
	$(MAKE) --no-print-directory build
	$(SUDO) $(MAKE) --no-print-directory install ARG_NO_CMAKE=1
	tests/run_all.sh

# Every libFuzzer target for FUZZ_SECONDS each (default 20), clang with ASan + UBSan in build-fuzz/.
fuzz: deps
	FUZZ_SECONDS=$(or $(FUZZ_SECONDS),20) tests/fuzz/run_fuzz.sh

# A 2-million-triangle build stopped at 20 moments (minutes of CPU, so outside make test).
cancel-check: cmake-all
	$(BUILD_DIR)/arg_unit_tests --gtest_also_run_disabled_tests \
	  --gtest_filter='BuildCancel.DISABLED_TwentyStopsOfATwoMillionTriangleBuild'

# The demo builds what it runs (the core's libraries, argtool, the extension): a tree it
# configures leaves the tests and benchmarks out, which need packages the demo does not install.
demo: deps-demo
	test -f $(BUILD_DIR)/CMakeCache.txt || \
	  $(CMAKE) -S . -B $(BUILD_DIR) $(CMAKE_FLAGS) -DARG_BUILD_TESTS=OFF -DARG_BUILD_BENCH=OFF
	$(MAKE) --no-print-directory all
	$(SUDO) $(MAKE) --no-print-directory install ARG_NO_CMAKE=1
	tools/demo/run.sh $(if $(MODELS),"$(MODELS)")

deb:
	tools/deb/build.sh

demo-stop:
	tools/browser/server.sh stop $(BUILD_DIR)/pg-demo
	tools/pg/cluster.sh stop $(BUILD_DIR)/pg-demo

distclean: demo-stop
	tools/pg/cluster.sh stop $(BUILD_DIR)/pg-test --remove
	rm -rf $(BUILD_DIR) build-asan build-fuzz .deps tools/browser/node_modules
