"""Checks of round_sim.py on cases with known answers (run by CTest: scaling_round_sim)."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import round_sim  # noqa: E402


class RoundSim(unittest.TestCase):
    def test_equal_constant_ranks_never_wait(self):
        t = np.full((8, 400), 2e-3)
        self.assertAlmostEqual(round_sim.staggered(t, 2), 1.0, places=12)
        self.assertAlmostEqual(round_sim.blocking(t, 2), 1.0, places=12)

    def test_a_steadily_slower_rank_sets_the_pace_in_both(self):
        # No protocol hides a persistent speed difference: efficiency = mean speed / slowest.
        t = np.vstack([np.full(2000, 1.0), np.full(2000, 1.5)])
        self.assertAlmostEqual(round_sim.blocking(t, 2), 2.5 / 3.0, places=12)
        self.assertAlmostEqual(round_sim.staggered(t, 2), 2.5 / 3.0, places=3)

    def test_staggering_absorbs_a_lag_below_one_group_round(self):
        # Rank 1 alternates slow and fast rounds (2.5 and 1.5 against rank 0's 2): a blocking loop
        # waits for it every slow round, 4 / 4.5 of the time busy; the staggered loop never waits
        # because the lag (0.5) stays below one group round (1).
        slow = np.tile([1.25, 1.25, 0.75, 0.75], 500)
        t = np.vstack([np.ones(2000), slow])
        self.assertAlmostEqual(round_sim.blocking(t, 2), 4.0 / 4.5, places=12)
        self.assertGreater(round_sim.staggered(t, 2), 0.999)

    def test_a_lag_beyond_the_slack_is_waited_for(self):
        # Each rank in turn takes 4 group rounds' time once every 10 rounds (equal work, 23 per 10
        # rounds). Blocking waits out every spike (23 / 26). Staggered: the lag swings by 3 between
        # the ends of the slack window of +-1 group round, so each spike costs the other rank a wait
        # of 1: 23 / 24.
        t = np.ones((2, 2000))
        t[0, 10::20] = 4.0
        t[1, ::20] = 4.0
        self.assertAlmostEqual(round_sim.blocking(t, 2), 23.0 / 26.0, places=12)
        self.assertAlmostEqual(round_sim.staggered(t, 2), 23.0 / 24.0, delta=0.002)

    def test_a_longer_lag_absorbs_what_one_round_cannot(self):
        # The spikes above (a lag of 3 group rounds) fit in a slack of 2 rounds (4 group rounds).
        t = np.ones((2, 2000))
        t[0, 10::20] = 4.0
        t[1, ::20] = 4.0
        self.assertGreater(round_sim.staggered(t, 2, lag=2), 0.999)

    def test_latency_costs_blocking_every_round_and_staggered_loops_nothing_when_hidden(self):
        t = np.ones((4, 1000))
        self.assertAlmostEqual(round_sim.blocking(t, 2, latency=0.2), 2.0 / 2.2, places=12)
        self.assertGreater(round_sim.staggered(t, 2, latency=0.2), 0.999)

    def test_bootstrap_keeps_the_mean_and_scales_with_copies(self):
        rng = np.random.default_rng(1)
        measured = [rng.normal(1.0, 0.1, 4096), rng.normal(1.2, 0.1, 4096)]
        one = round_sim.bootstrap(measured, 64, 2, 64, rng)
        two = round_sim.bootstrap(measured, 64, 2, 64, rng, copies=2)
        self.assertEqual(one.shape, (64, 4096))
        self.assertAlmostEqual(one.mean(), 1.1, delta=0.01)
        self.assertAlmostEqual(two.mean(), 2.2, delta=0.02)
        # Independent copies: relative spread shrinks by sqrt 2.
        self.assertAlmostEqual((two.std() / two.mean()) / (one.std() / one.mean()), 2 ** -0.5, delta=0.05)

    def test_a_longer_render_loses_less_to_the_end_spread(self):
        # Blocks of 64 group rounds run at speed 1 or 1.5 at random: the ranks' totals spread as the
        # square root of the block count, their mean linearly, so a render 16 times as long loses
        # about a quarter as much (no per-round barrier: unlimited lag).
        rng = np.random.default_rng(3)
        measured = [np.repeat(rng.choice([1.0, 1.5], 64), 64) for _ in range(2)]
        short = round_sim.bootstrap(measured, 256, 2, 64, rng)
        long = round_sim.bootstrap(measured, 256, 2, 64, rng, length=16 * 4096)
        self.assertEqual(short.shape, (256, 4096))
        self.assertEqual(long.shape, (256, 16 * 4096))
        loss_short = 1.0 - round_sim.staggered(short, 2, lag=short.shape[1])
        loss_long = 1.0 - round_sim.staggered(long, 2, lag=long.shape[1])
        self.assertGreater(loss_short, 0.02)
        self.assertAlmostEqual(loss_long / loss_short, 0.25, delta=0.1)


if __name__ == "__main__":
    unittest.main()
