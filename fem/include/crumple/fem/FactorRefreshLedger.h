// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple::fem
{

/// When a refreshing implicit solver (TetSolverSettings::mFactorRefreshByCost) refreshes its factor although
/// no single solve was long: the account of what the factor's frames have cost since they were set, kept as
/// solver state (integers and one ratio, so a copy or a replay decides alike). An implementation detail of
/// TetSolver, public only because the solver holds it by value (as TetSolverWorkspace).
///
/// Rent or buy (the ski-rental problem, Karlin et al. 1988): each solve at a linearisation other than the
/// factor's own pays the iterations beyond cBaseIterations (what a solve takes even right after a refresh:
/// the next linearisation is never exactly the factor's); once those add up to what a refresh costs, the
/// factor is refreshed. Where the extra iterations come from frames that have drifted (a fence settling at
/// other frames than those of its last refresh: 4-5 iterations a step for a hundred steps), that costs at
/// most twice the best choice in hindsight. Where they do not (pieces turning fast between two solves, which
/// no refresh can follow), each refresh would buy nothing: a refresh whose next solve costs as much beyond
/// the base as the solves before it did doubles the cost to be reached before the next (up to cMaxMultiplier
/// refreshes' worth), and one that pays brings it back to one.
class FactorRefreshLedger
{
  public:
    /// Iterations a solve takes at a linearisation other than, but near, its factor's (the CG tolerance of
    /// 1e-6 needs two unless the preconditioner is exact)
    static constexpr int cBaseIterations = 2;
    /// The most refreshes' worth of extra iterations waited for after refreshes that bought nothing
    static constexpr int cMaxMultiplier = 8;

    /// The factor's frames were set: by a refresh this ledger asked for (inByCost: its next solve judges it)
    /// or by anything else (a long solve, a crack, new anchors; no judgement).
    void FramesSet(bool inByCost)
    {
        // intent: the first solve after the frames were set adds nothing, so the rate is over the others
        mTriggerRate = inByCost && mSolves > 1 ? static_cast<double>(mExcess) / (mSolves - 1) : 0.0;
        mExcess = 0;
        mSolves = 0;
    }

    /// A solve of inIterations conjugate-gradient iterations with the factor. The first after the frames were
    /// set is at their own linearisation and costs nothing; the second says whether a refresh the ledger
    /// asked for paid.
    void CountSolve(int inIterations)
    {
        ++mSolves;
        if (mSolves == 1)
            return;
        const int excess = inIterations > cBaseIterations ? inIterations - cBaseIterations : 0;
        if (mSolves == 2 && mTriggerRate > 0.0)
        {
            mMultiplier = excess >= mTriggerRate
                              ? (2 * mMultiplier < cMaxMultiplier ? 2 * mMultiplier : cMaxMultiplier)
                              : 1;
            mTriggerRate = 0.0;
        }
        mExcess += excess;
    }

    /// True when the iterations counted since the frames were set have reached inRefreshCost (iterations:
    /// TetFactoredPreconditioner::GetRefreshCostInIterations) times the multiplier.
    bool ShouldRefresh(double inRefreshCost) const { return mExcess >= inRefreshCost * mMultiplier; }

    /// Extra iterations counted since the frames were set
    int GetExcess() const { return mExcess; }
    /// The refreshes' worth of extra iterations waited for now (1 after a refresh that paid)
    int GetMultiplier() const { return mMultiplier; }

  private:
    int mExcess = 0;           // iterations beyond cBaseIterations, over the solves since the frames were set
    int mSolves = 0;           // solves since the frames were set
    int mMultiplier = 1;       // in [1, cMaxMultiplier]
    double mTriggerRate = 0.0; // extra iterations per solve that asked for the last refresh; 0: none to judge
};

} // namespace crumple::fem
