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
# Left out here (they run in scripts/test.sh): the tests that repeat code other tests
# run under the sanitizers too, over a dense quadrature, thousands of samples, many
# renders or many airs. The sanitizers find a memory or undefined-behaviour error by
# running its code once, not by running it often. With gtest's JSON timings: those
# listed 2026-12-02 took 50–170 s each at -O1, those added 2026-12-03 15–200 s each at
# -O2 (an atmosphere's tables alone take 22 s instrumented, 1.3 s in Release), those
# added 2026-12-04 40–135 s each beside the one noted. The whole suite at -O2 ran 1070 s
# wall in two shards; without these 527 s. What still runs covers their
# code at fewer points: the renders, the reference images of every example, the
# extreme scenes, one sweep and one animation through the CLI, the other tests of the
# shared tables, the path-integrator tests.
heavy=(
  # dense quadratures and many samples of one code path
  SpecularSky.AdaptiveBandSearchMatchesADenseQuadrature
  SkyLight.CanyonFloorSeesTheSkyFractionOfTheClosedForm
  SkyLight.UnobstructedIrradianceMatchesADenseQuadratureOfTheSky
  SkyIrradiance.MatchesABruteForceIntegralOverTheSphere
  Renderer.WhitePlaneMatchesTheSpectrumCommandsIlluminances
  SpectrumCommand.CsvHasEveryNanometreAndMatchesTheModel
  # a full spectrum run too (10 s in Release); `sky`'s code runs here in the other tests
  SkyCommand.TakesTheSunsAltitudeAsSeenAsSpectrumDoes
  ReflectionSampling.MeanWeightIsTheDirectionalAlbedo
  ReflectionSampling.DirectionsFollowTheStatedDensity
  FogSkyLight.AdaptivePitchMatchesFineFixedSteps
  FogSkyLight.TableMatchesDirectQuadratureInDenseFog
  FogRender.CameraTableMatchesDirectIntegrationInDenseFog
  FogSurfaceLight.IrradianceOfAnyPlaneMatchesADenseQuadratureOfTheIncomingLight
  FogDiffuseField.ConservesTheSunsEnergy
  LampRender.GlowShadowsAreExactWithinTheReachAndBeyondItWhenTheyMatter
  # 2.6 s in Release; the share's grid test runs here
  CloudSkyShare.AgreesWithADenseQuadratureForAnyFacing
  # thirty fogs' multiple-scattering fields, the densest with hundreds of levels (2480 s
  # instrumented, 2026-12-04: CI took 76 minutes); extreme fogs still run here at random
  # in ExtremeScenes.RenderFiniteOrAreRefusedNeverAnInternalError
  FogSkyLight.NoNanForExtremeInputs
  WeatherConditions.ClearHoursOfTheSharedFileMatchTheModel
  # 187 hours of the shared file; the efficacies' code runs here in the fixture's test
  LuminousEfficacy.AFileWithoutIlluminancesGetsTheSharedFilesOwnFromItsIrradiances
  SkyLightCacheExamples.Fig7AtSmallSizesStaysNearTheExactSkyLight
  # four renders of Fig. 9, two with the exact sky light at every sample (8 s in Release)
  NightSkyLightCache.LampsAndGlowOutshiningTheSkyCostNothingVisibleAtDusk
  SkyLightCacheExamples.Fig7CacheAddsLittleToTheQuadraturesOwnError
  # the atmosphere's Monte Carlo reference (test code; about 25 s of CPU in Release for
  # each estimator), which whichever of these runs first in a shard computes
  'MultipleScattering.*MonteCarlo*'
  'MultipleScattering.*SunlitLine*'
  MultipleScattering.OrdersFallGeometricallyAndConverge
  # path-traced comparisons; their code runs here through the closed-form tests of the
  # same features and PathIntegrator's
  PathFog.SlabUnderUniformSkyMatchesAddingDoubling
  FogMultipleScattering.LightsSurfacesInTheFogWithTheFogsOwnLight
  FogMultipleScattering.TheBlocksOfFig8cInTheirOwnShadowAgainstThePathTracer
  CanyonLight.ShadedWallAgainstThePathTracer
  # the same at 5 and 20 m, h/w 2 and 4 (14 s in Release, 200,000 paths a point); the obstacles' sun
  # map runs here in ObstacleSkyLight's tests and every render
  CanyonLight.TheShadedWallHoldsAtOtherWidths
  # the same under an oblique sun (8 s in Release)
  CanyonLight.TheShadedWallHoldsUnderAnObliqueSun
  # the sunlit cloud slab (57 s each in Release under ctest -j2); its spike paths run
  # here in PathIntegrator's cloud tests and ExtremeScenes
  'CloudSlab.SunAt*'
  FogMultipleScattering.MatchesThePathTracedReferenceWhereTheFieldIsAzimuthallySymmetric
  FogMultipleScattering.FollowsTheSunInAzimuthWithTheDropletPhaseFunction
  ReflectedSunFig7.AluminiumTowerAgainstThePathTracer
  CloudSlab.SkyLitMatchesPathTracedReference
  # many renders of one scene, or renders in many airs
  FogContrast.BlackTargetsFollowKoschmiedersLawInTheRenderedImage
  HorizonLine.NoRowStandsOutWhereTheGroundPlaneMeetsTheSky
  HorizonLine.FoggedGroundBesideASmallBuildingTakesNothingHugeFromTheCache
  CloudRender.DistantCloudFadesIntoHazeThroughTheAirBeforeIt
  PublishedValues.RayleighOnlyAtmosphereAttenuatesTheZenithSunByItsOpticalDepth
  Cli.OutputDoesNotDependOnThreadCount
  CliNumbers.NonFiniteAndOverflowingValuesAreRefusedByEveryNumericOption
  # sweeps and animations (one of each runs here), shards, the browser
  SweepCommand.WritesEveryCombinationAndTheSheet
  SweepCommand.Fig7ExampleSweepsAtATinySize
  SweepCommand.StatisticsOverHoursGatherIntoOneCsvAndAPlot
  SweepCommand.StatisticsOverWeatherFileHoursLieInOneYear
  AnimateCommand.FramesInOrderAtOneExposureWithViewerVideoAndStatistics
  AnimateCommand.ViewerInChromiumShowsEachFrameWithItsLabel
  ReportInBrowser.ImagesLoadAndReadOutShowsTheExrLuminance
  SplitRuns.ShardsMergeIntoTheSameSweepAndAnimation
  # thirteen and three airs' tables; the sharing itself runs here in the other
  # AtmosphereTables tests
  AtmosphereTables.EveryChangeOfTheAirBuildsItsOwn
  AtmosphereTables.ThreadsAskingForAFewAirsAtOnceEachGetTheirAirs
  # 30–80 s each instrumented (2026-12-06; the suite ran 892 s wall, CI 64 minutes).
  # The same code runs here in: SpectrumCommand.PlotIsWritten (the spectrum command);
  # the reference images of Fig. 7 and the house (the cache's rules, the canyon's
  # light); FogBehindSurfaces' and FogSurfaceLight's other tests (the hidden light, the
  # field on surfaces); the fog's other path-integrator tests; Fig. 10's reference
  # images (clouds); Fig. 9's and the other exposure tests (lamps at night)
  SpectrumCommand.WithoutCsvOrPlotPrintsTheIlluminances
  SkyLightCacheExamples.ALoneCornerDoesNotStandInAcrossARecess
  CanyonLight.TheShadedWallDoesNotDependOnHowTheSunlitOneIsCutIntoTriangles
  FogMultipleScattering.TheGroundInFig8csShadowsAgainstThePathTracer
  FogMultipleScattering.TheFogInFrontOfADarkWallLosesTheLightTheWallHides
  FogMultipleScattering.SurfacesSeenThroughTheFogKeepTheLightScatteredStraightOn
  FogSurfaceLight.AnUpwardFacingPlaneGetsTheFieldsDownwardFlux
  CloudRender.BaseIsDarkerThanTheSkyAtLowSun
  AutomaticExposure.LampLitStreetAtNightIsNotBurntByItsDarkSky
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
