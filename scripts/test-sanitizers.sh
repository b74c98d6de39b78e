#!/usr/bin/env bash
# CI, after scripts/test.sh: the whole test suite built with Clang's AddressSanitizer
# and UndefinedBehaviorSanitizer (scripts/build-asan.sh, into build-asan/). Fails on a
# failing test or on any sanitizer report, also from a process a test starts (the
# skylit program), since every report is written to build-asan/sanitizer-logs/.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
scripts/build-asan.sh
echo "test-sanitizers: build took $((SECONDS - start)) s" >&2

logs=$PWD/build-asan/sanitizer-logs
rm -rf "$logs" && mkdir -p "$logs"
# Embree and TBB are not instrumented; nothing here needs to be turned off for them
# (no false positives seen). Leak checking stays on.
export ASAN_OPTIONS="log_path=$logs/asan:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="log_path=$logs/ubsan:print_stacktrace=1:halt_on_error=1"

# The test program itself in two shards, not CTest's one process per test: the
# atmosphere tables that many tests share are then built once per shard rather than
# once per test, which under the sanitizers is most of the time.
# Left out here (they run in scripts/test.sh): the accuracy checks that repeat one
# code path over a dense quadrature or thousands of samples, and the sweeps that
# render the same cell code many times. Under the sanitizers each took 50–170 s (a
# quarter of this run, measured 2026-12-02 with gtest's JSON timings). Their code runs
# here anyway, at fewer points: the renders, the path-integrator tests (reflection
# sampling), the reference images (the specular band search, sky light) and the
# remaining sweep test (sweep cells) go through it.
heavy=(
  SweepCommand.WritesEveryCombinationAndTheSheet
  SweepCommand.Fig7ExampleSweepsAtATinySize
  SpecularSky.AdaptiveBandSearchMatchesADenseQuadrature
  SkyLight.CanyonFloorSeesTheSkyFractionOfTheClosedForm
  Renderer.WhitePlaneMatchesTheSpectrumCommandsIlluminances
  PathFog.SlabUnderUniformSkyMatchesAddingDoubling
  SpectrumCommand.CsvHasEveryNanometreAndMatchesTheModel
  ReflectionSampling.MeanWeightIsTheDirectionalAlbedo
  ReflectionSampling.DirectionsFollowTheStatedDensity
  SkyLight.UnobstructedIrradianceMatchesADenseQuadratureOfTheSky
  SkyIrradiance.MatchesABruteForceIntegralOverTheSphere
  MultipleScattering.MonteCarloFirstOrderMatchesSingleScattering
  # the same Monte Carlo reference (about 25 s of CPU in Release, both estimators), which
  # whichever of these runs first in a shard computes.
  MultipleScattering.SunlitLineEstimatorAgreesWithTheCollisionEstimator
  MultipleScattering.SunlitLineFirstOrderMatchesSingleScattering
  MultipleScattering.ScatteringOrdersMatchTheSunlitLineEstimatorAtTwilight
  # issue 20: some twenty small renders to compare merged shards with one process;
  # the shards' file format (XyzFile) and the animation (AnimateCommand) run here.
  SplitRuns.ShardsMergeIntoTheSameSweepAndAnimation
  FogMultipleScattering.MatchesThePathTracedReferenceWhereTheFieldIsAzimuthallySymmetric
  # path-traced comparisons of this session (fog's azimuthal terms, the reflected sun on
  # Fig. 7): their code runs here through the closed-form tests of the same features.
  FogMultipleScattering.FollowsTheSunInAzimuthWithTheDropletPhaseFunction
  ReflectedSunFig7.AluminiumTowerAgainstThePathTracer
  # thirteen airs' tables built to check the shared tables' key; the sharing itself
  # (and its threads) runs here in the other AtmosphereTables tests.
  AtmosphereTables.EveryChangeOfTheAirBuildsItsOwn
)
filter="-$(IFS=:; echo "${heavy[*]}")"

status=0
run_start=$SECONDS
cd build-asan
for shard in 0 1; do
  GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard bin/skylit_tests --gtest_brief=1 --gtest_filter="$filter" >"tests-shard$shard.log" 2>&1 &
  pids[$shard]=$!
done
for shard in 0 1; do
  if ! wait "${pids[$shard]}"; then
    echo "test-sanitizers: shard $shard failed:" >&2
    cat "tests-shard$shard.log" >&2
    status=1
  fi
done
cd ..
echo "test-sanitizers: tests took $((SECONDS - run_start)) s" >&2
if compgen -G "$logs/*" >/dev/null; then
  echo "test-sanitizers: sanitizer reports:" >&2
  cat "$logs"/* >&2
  status=1
fi
exit $status
