# AuRoRA-ROS: `make demo` flies the mission with delay and writes a report to
# out/; `make test` runs every gtest and rostest. Both install what is
# missing and build first.
SHELL := /bin/bash
# ROS tools and catkin need Debian's python3 (with the ROS modules), not a
# pyenv one that may come first in PATH.
export PATH := /usr/bin:/bin:$(PATH)
BUILD ?= build
JOBS ?= 2
ROS_SETUP := $(firstword $(wildcard /opt/ros/noetic/setup.bash))
SOURCE_ROS := $(if $(ROS_SETUP),source $(ROS_SETUP) &&,)

.PHONY: all deps build install test demo bench notebook clean

all: build

deps:
	./scripts/install_deps.sh

build: deps
	@# catkin bakes the test environment (setup_cached.sh) at configure time and
	@# puts the devel python path in only if it exists then: create it first.
	mkdir -p $(BUILD)/devel/lib/python3/dist-packages
	$(SOURCE_ROS) cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release \
	  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_DEVEL_PREFIX=$(abspath $(BUILD))/devel \
	  -DCMAKE_INSTALL_PREFIX=$(abspath $(BUILD))/install \
	  -DCATKIN_ENABLE_TESTING=ON > $(BUILD)/cmake.log 2>&1 || { cat $(BUILD)/cmake.log; exit 1; }
	$(SOURCE_ROS) $(MAKE) -C $(BUILD) -j$(JOBS) all tests

# The install space (catkin_make's layout): $(BUILD)/install; source its
# setup.bash to run from there (the install_space rostest does).
install: build
	cmake --install $(BUILD)

test: build
	./scripts/run_tests.sh $(BUILD)

demo: build
	./scripts/run_demo.sh $(BUILD)

# Jupyter on notebooks/ (open the URL it prints); `import aurora` works there.
# NOTEBOOK_ARGS passes options (e.g. --no-browser --port 8899); as root
# (containers) Jupyter needs --allow-root.
notebook: build
	$(SOURCE_ROS) source $(BUILD)/devel/setup.bash && jupyter notebook --notebook-dir=notebooks \
	  $(if $(filter 0,$(shell id -u)),--allow-root,) $(NOTEBOOK_ARGS)

bench: build
	./bench/realtime_loop.sh $(BUILD)
	./bench/sweep.sh $(BUILD)
	./bench/sweep_scale.sh $(BUILD)
	./bench/report.sh $(BUILD)
	./bench/laws.sh $(BUILD)
	./bench/links.sh $(BUILD)
	./bench/formation.sh $(BUILD)
	./bench/formation_robots.sh $(BUILD)
	./bench/predictor.sh $(BUILD)
	./bench/python.sh $(BUILD)

clean:
	rm -rf $(BUILD) out
