// Calls every public member of the packed Verve.dll under Mono, the runtime Unity's scripting is built
// on, against a freshly built libverve. Compiled by Mono's own compiler (mcs, C# 7) against the
// netstandard facade, so a BCL member the binding uses but Mono lacks fails here with
// MissingMethodException, as it would in a Unity game. Run by run.sh.
//
// The list of calls is Exercise() below. The run fails when a public member of Verve.dll has no Check
// naming it, or a Check names a member that does not exist: a new public member gets a Check here.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using Verve;

static class MonoHost
{
    static readonly HashSet<string> Checked = new HashSet<string>();
    static int s_failures;

    static int Main()
    {
        string runtime = RuntimeName();
        Console.WriteLine("runtime: " + runtime);
        if (!runtime.StartsWith("Mono", StringComparison.Ordinal)) return 2;
        Exercise();
        CheckCoverage();
        Console.WriteLine(s_failures == 0 ? "mono host: all checks passed" : "mono host: " + s_failures + " check(s) failed");
        return s_failures == 0 ? 0 : 1;
    }

    // Shared by the checks, in order: the options, the agent made from them, its save.
    static AgentOptions s_options;
    static Agent s_agent;
    static byte[] s_save;

    static void Exercise()
    {
        Check("VerveLibrary.get_NativeVersionNumber(); VerveLibrary.get_NativeVersion(); VerveLibrary.get_BindingVersion(); VerveLibrary.IsCompatible(Int32)", () =>
        {
            Require(VerveLibrary.NativeVersionNumber == VerveLibrary.BindingVersionNumber, "native and binding versions differ");
            Require(VerveLibrary.NativeVersion.Equals(VerveLibrary.BindingVersion), "Version objects differ");
            Require(VerveLibrary.IsCompatible(VerveLibrary.NativeVersionNumber), "the loaded library is not compatible");
            Require(!VerveLibrary.IsCompatible(0x010000), "1.0.0 reported compatible");
        });

        Check("AgentOptions..ctor(); AgentOptions.AddDiscreteSensor(Int32); AgentOptions.AddContinuousSensor(Boolean); " +
              "AgentOptions.ClearSensors(); AgentOptions.get_DiscreteSensors(); AgentOptions.get_ContinuousSensorCircular()", () =>
        {
            var o = new AgentOptions().AddDiscreteSensor(4).AddContinuousSensor(true);
            Require(o.DiscreteSensors.SequenceEqual(new[] { 4 }) && o.ContinuousSensorCircular.SequenceEqual(new[] { true }), "sensors not recorded");
            o.ClearSensors();
            Require(o.DiscreteSensors.Count == 0 && o.ContinuousSensorCircular.Count == 0, "ClearSensors left sensors");
            Expect<ArgumentOutOfRangeException>(() => o.AddDiscreteSensor(-1));
            for (int i = 0; i < AgentOptions.MaxContinuousSensors; i++) o.AddContinuousSensor();
            Expect<InvalidOperationException>(() => o.AddContinuousSensor());
        });

        // Every setter with a value other than the default, every getter read back through the library.
        Check("AgentOptions.set_Actions(Int32); AgentOptions.set_Resolution(Int32); AgentOptions.set_RbfAllocation(RbfAllocation); " +
              "AgentOptions.set_TauValue(Single); AgentOptions.set_TauDiscount(Single); AgentOptions.set_TauEligibility(Single); " +
              "AgentOptions.set_PolicyMultiplier(Single); AgentOptions.set_TraceThreshold(Single); AgentOptions.set_Seed(UInt64); " +
              "AgentOptions.set_Planning(Boolean); AgentOptions.set_TauModel(Single); AgentOptions.set_MaxPlanningSteps(Int32); " +
              "AgentOptions.set_PlanningUncertaintyThreshold(Single); AgentOptions.set_Curiosity(Curiosity); " +
              "AgentOptions.set_CuriosityFactor(Single); AgentOptions.set_PlanningAccumulatesUncertainty(Boolean); " +
              "AgentOptions.set_LearnFromRealSteps(Boolean); AgentOptions.set_DiscretePrediction(DiscretePrediction); AgentOptions.set_MaxRbfs(Int64); " +
              "Agent..ctor(AgentOptions); Agent.get_Options(); " +
              "AgentOptions.get_Actions(); AgentOptions.get_Resolution(); AgentOptions.get_RbfAllocation(); " +
              "AgentOptions.get_TauValue(); AgentOptions.get_TauDiscount(); AgentOptions.get_TauEligibility(); " +
              "AgentOptions.get_PolicyMultiplier(); AgentOptions.get_TraceThreshold(); AgentOptions.get_Seed(); " +
              "AgentOptions.get_Planning(); AgentOptions.get_TauModel(); AgentOptions.get_MaxPlanningSteps(); " +
              "AgentOptions.get_PlanningUncertaintyThreshold(); AgentOptions.get_Curiosity(); AgentOptions.get_CuriosityFactor(); " +
              "AgentOptions.get_PlanningAccumulatesUncertainty(); AgentOptions.get_LearnFromRealSteps(); AgentOptions.get_DiscretePrediction(); " +
              "AgentOptions.get_MaxRbfs()", () =>
        {
            s_options = new AgentOptions
            {
                Actions = 3, Resolution = 8, RbfAllocation = RbfAllocation.Full, TauValue = 0.2f, TauDiscount = 0.9f,
                TauEligibility = 0.15f, PolicyMultiplier = 4f, TraceThreshold = 0.02f, Seed = 7, Planning = true,
                TauModel = 0.05f, MaxPlanningSteps = 4, PlanningUncertaintyThreshold = 0.4f, Curiosity = Curiosity.Novelty,
                CuriosityFactor = 2f, PlanningAccumulatesUncertainty = false, LearnFromRealSteps = false,
                DiscretePrediction = DiscretePrediction.Ordinal, MaxRbfs = 5000,
            }.AddDiscreteSensor(2).AddContinuousSensor(true);
            s_agent = new Agent(s_options);
            AgentOptions back = s_agent.Options;
            Require(back.Actions == 3 && back.Resolution == 8 && back.RbfAllocation == RbfAllocation.Full &&
                    back.TauValue == 0.2f && back.TauDiscount == 0.9f && back.TauEligibility == 0.15f &&
                    back.PolicyMultiplier == 4f && back.TraceThreshold == 0.02f && back.Seed == 7 && back.Planning &&
                    back.TauModel == 0.05f && back.MaxPlanningSteps == 4 && back.PlanningUncertaintyThreshold == 0.4f &&
                    back.Curiosity == Curiosity.Novelty && back.CuriosityFactor == 2f && !back.PlanningAccumulatesUncertainty &&
                    !back.LearnFromRealSteps && back.DiscretePrediction == DiscretePrediction.Ordinal && back.MaxRbfs == 5000 &&
                    back.DiscreteSensors.SequenceEqual(new[] { 2 }) && back.ContinuousSensorCircular.SequenceEqual(new[] { true }),
                    "Agent.Options differs from the options it was made with");
        });

        Check("Agent.Update(Single, Int32[], Single[], Single); Agent.Update(Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single); " +
              "Agent.EndEpisode(Single); Agent.ResetShortTermMemory(); Agent.get_Value(); Agent.get_TdError(); Agent.get_RbfCount()", () =>
        {
            RunTrials(s_agent, 3);
            Require(s_agent.RbfCount > 0, "no RBFs after updates");
            Require(!float.IsNaN(s_agent.Value) && !float.IsNaN(s_agent.TdError), "NaN value or TD error");
            s_agent.ResetShortTermMemory();
        });

        Check("Agent.get_Stats(); AgentStats.get_Steps(); AgentStats.get_RbfCount(); AgentStats.get_LiveTraces(); AgentStats.get_Value(); " +
              "AgentStats.get_TdError(); AgentStats.get_ModelError(); AgentStats.get_PredictedUncertainty(); " +
              "AgentStats.get_PlanningSteps(); AgentStats.get_CuriosityReward(); AgentStats.get_RbfBudgetHits(); " +
              "AgentStats.get_ClampedRewards(); AgentStats.ToString()", () =>
        {
            AgentStats s = s_agent.Stats;
            Require(s.Steps == 3 * StepsPerTrial && s.RbfCount == s_agent.RbfCount, "stats disagree with the run: " + s);
            Require(s.LiveTraces >= 0 && s.PlanningSteps >= 0 && !float.IsNaN(s.Value + s.TdError + s.ModelError +
                    s.PredictedUncertainty + s.CuriosityReward), "bad stats: " + s);
            Require(s.RbfBudgetHits == 0 && s.ClampedRewards == 0, "rewards in [0, 1] under the budget were counted: " + s);
            Require(s.ToString().StartsWith("steps=" + s.Steps, StringComparison.Ordinal), "AgentStats.ToString: " + s);
        });

        // The log hook is a native-to-managed callback: it must be callable under Mono (and IL2CPP).
        Check("VerveLibrary.TakeWarnings()", () =>
        {
            VerveLibrary.TakeWarnings();
            using (var agent = new Agent(new AgentOptions { Actions = 2 }.AddDiscreteSensor(2)))
            {
                agent.Update(0f, new[] { 0 }, null, 0.1f);
                agent.Update(4.5f, new[] { 1 }, null, 0.1f);
                Require(agent.Stats.ClampedRewards == 1, "ClampedRewards: " + agent.Stats);
                string[] warnings = VerveLibrary.TakeWarnings();
                Require(warnings.Length == 1 && warnings[0].Contains("a reward of 4.5 was clamped to [-1, 1]"),
                        "warnings: " + string.Join(" | ", warnings));
                Require(VerveLibrary.TakeWarnings().Length == 0, "a second read repeated the warning");
            }
        });

        Check("Agent.get_Learning(); Agent.set_Learning(Boolean)", () =>
        {
            Require(s_agent.Learning, "a new agent does not learn");
            s_agent.Learning = false;
            Require(!s_agent.Learning, "Learning = false ignored");
            s_agent.Learning = true;
        });

        Check("Agent.Update(Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, ReadOnlySpan<Byte>); " +
              "Agent.get_ActionProbabilities(); Agent.get_ActionSelection(); Agent.set_ActionSelection(ActionSelection); " +
              "Agent.TruncateEpisode(Single); AgentOptions.set_PolicyWeightBound(Single); AgentOptions.get_PolicyWeightBound(); " +
              "AgentOptions.set_Adaptation(Adaptation); AgentOptions.get_Adaptation()", () =>
        {
            Require(new AgentOptions().Adaptation == Adaptation.All, "the adaptations are not on by default");
            var options = new AgentOptions { Actions = 3, PolicyWeightBound = 4f, Adaptation = Adaptation.Horizon }.AddContinuousSensor(false);
            using (var agent = new Agent(options))
            {
                Require(agent.Options.PolicyWeightBound == 4f, "PolicyWeightBound did not reach the agent");
                Require(agent.Options.Adaptation == Adaptation.Horizon, "Adaptation did not reach the agent");
                ReadOnlySpan<byte> onlyFirst = new byte[] { 1, 0, 0 };
                for (int i = 0; i < 20; ++i)
                {
                    int action = agent.Update(0.1f, ReadOnlySpan<int>.Empty, new[] { 0.05f * i }, 0.1f, onlyFirst);
                    Require(action == 0, "a masked action was chosen: " + action);
                }
                float[] p = agent.ActionProbabilities;
                Require(p.Length == 3 && p[0] == 1f && p[1] == 0f && p[2] == 0f, "probabilities under the mask: " + string.Join(",", p));
                Require(agent.ActionSelection == ActionSelection.Sample, "sampling is not the default");
                agent.ActionSelection = ActionSelection.Greedy;
                Require(agent.ActionSelection == ActionSelection.Greedy, "ActionSelection = Greedy ignored");
                agent.TruncateEpisode(-0.5f);
            }
        });

        // Action branches: {3, 2} through the descriptor, a per-branch mask, probabilities per branch, split/join.
        Check("AgentOptions.get_ActionBranches(); AgentOptions.SetActionBranches(Int32[]); AgentOptions.ClearActionBranches(); " +
              "Agent.SplitAction(Int32); Agent.JoinAction(Int32[])", () =>
        {
            var options = new AgentOptions { Seed = 5 }.AddContinuousSensor().SetActionBranches(3, 2);
            Require(options.Actions == 6, "SetActionBranches did not set Actions to the product");
            using (var agent = new Agent(options))
            {
                Require(agent.Options.ActionBranches.SequenceEqual(new[] { 3, 2 }), "the branches did not come back");
                byte[] mask = { 1, 0, 1, 0, 1 };
                for (int step = 0; step < 50; step++)
                {
                    int[] c = agent.SplitAction(agent.Update(0.1f, new int[0], new[] { (float)Math.Sin(step) }, 0.1f, mask));
                    Require((c[0] == 0 || c[0] == 2) && c[1] == 1, "a chosen action broke the per-branch mask");
                }
                float[] p = agent.ActionProbabilities;
                Require(p.Length == 5 && Math.Abs(p[3] + p[4] - 1f) < 1e-5f, "probabilities are not per branch");
                Require(agent.JoinAction(2, 1) == 5 && agent.JoinAction(agent.SplitAction(4)) == 4, "split/join do not round trip");
                Expect<VerveException>(() => agent.JoinAction(3, 0));
            }
            options.ClearActionBranches();
            Require(options.ActionBranches.Count == 0, "ClearActionBranches left branches");
        });

        // Continuous actions: an agent that only steers (Actions 0 means 1), the values read both ways, greedy = mean.
        Check("AgentOptions.get_ContinuousActions(); AgentOptions.set_ContinuousActions(Int32); " +
              "Agent.get_ContinuousAction(); Agent.GetContinuousAction(Span<Single>)", () =>
        {
            var options = new AgentOptions { Actions = 0, ContinuousActions = 2, Seed = 4 }.AddContinuousSensor();
            Require(new AgentOptions().ContinuousActions == 0 && options.ContinuousActions == 2, "ContinuousActions not recorded");
            Expect<ArgumentOutOfRangeException>(() => options.ContinuousActions = AgentOptions.MaxContinuousActions + 1);
            using (var agent = new Agent(options))
            {
                Require(agent.Options.Actions == 1 && agent.Options.ContinuousActions == 2, "the steering agent's actions did not come back");
                Require(agent.ContinuousAction.SequenceEqual(new[] { 0f, 0f }), "continuous actions before any update are not 0");
                var values = new float[2];
                for (int step = 0; step < 50; step++)
                {
                    Require(agent.Update(0.1f, new int[0], new[] { (float)Math.Sin(step) }, 0.1f) == 0, "the one discrete action is not 0");
                    agent.GetContinuousAction(values);
                    Require(values[0] >= -1f && values[0] <= 1f && values[1] >= -1f && values[1] <= 1f, "a continuous action outside [-1, 1]");
                    Require(agent.ContinuousAction.SequenceEqual(values), "the two read-outs disagree");
                }
                agent.ActionSelection = ActionSelection.Greedy;
                agent.Learning = false;
                agent.Update(0f, new int[0], new[] { 0.5f }, 0.1f);
                float[] mean = agent.ContinuousAction;
                agent.Update(0f, new int[0], new[] { 0.5f }, 0.1f);
                Require(agent.ContinuousAction.SequenceEqual(mean), "greedy gave other values for the same observation");
                Expect<VerveException>(() => agent.GetContinuousAction(new float[3]));
            }
        });

        // Sensor groups: Auto's lattices for 12 sensors (Full allocation shows them), custom groups there and back.
        Check("AgentOptions.get_Grouping(); AgentOptions.set_Grouping(SensorGrouping); AgentOptions.AddSensorGroup(Int32[]); " +
              "AgentOptions.get_SensorGroups(); AgentOptions.ClearSensorGroups()", () =>
        {
            var options = new AgentOptions { Actions = 3, RbfAllocation = RbfAllocation.Full, Resolution = 10 };
            for (int i = 0; i < 12; i++) options.AddContinuousSensor(false);
            Require(options.Grouping == SensorGrouping.Auto && options.SensorGroups.Count == 0, "Auto with no groups is not the default");
            using (var agent = new Agent(options))
                Require(agent.RbfCount == 12 * 10 + 11 * 100, "Auto over 12 sensors made " + agent.RbfCount + " RBFs");
            for (int i = 0; i < 12; i++) options.AddSensorGroup(i);
            options.AddSensorGroup(1, 0);
            Require(options.Grouping == SensorGrouping.Custom, "AddSensorGroup did not set Custom");
            using (var agent = new Agent(options))
            {
                Require(agent.RbfCount == 12 * 10 + 100, "the custom groups made " + agent.RbfCount + " RBFs");
                var back = agent.Options.SensorGroups;
                Require(back.Count == 13 && back[12].SequenceEqual(new[] { 0, 1 }), "the groups did not come back");
            }
            options.ClearSensorGroups();
            options.Grouping = SensorGrouping.Joint;
            Require(options.SensorGroups.Count == 0, "ClearSensorGroups left groups");
            options.AddSensorGroup(0);
            options.Grouping = SensorGrouping.Auto;
            Expect<ArgumentException>(() => new Agent(options));
        });

        Check("Agent.UpdateDemonstrated(Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, Int32, ReadOnlySpan<Byte>); " +
              "Agent.Teach(Single); Agent.Replay(Recording); Recording..ctor(Agent); " +
              "Recording.AddStep(Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, Int32); " +
              "Recording.AddEndEpisode(Single); Recording.AddTruncation(Single); Recording.get_Count(); " +
              "Recording.Save(String); Recording.Load(String); Recording.SaveToBytes(); " +
              "Recording.LoadFromBytes(ReadOnlySpan<Byte>); Recording.Dispose()", () =>
        {
            var options = new AgentOptions { Actions = 3, Seed = 2 }.AddContinuousSensor(false);
            using (var shown = new Agent(options))
            using (var replayed = new Agent(options))
            {
                var recording = new Recording(shown);
                shown.Teach(0f);
                for (int i = 0; i < 12; ++i)
                {
                    float[] c = { 0.1f * i - 0.5f };
                    shown.UpdateDemonstrated(0f, ReadOnlySpan<int>.Empty, c, 0.1f, 2, ReadOnlySpan<byte>.Empty);
                    recording.AddStep(0f, ReadOnlySpan<int>.Empty, c, 0.1f, 2);
                }
                shown.Teach(1f);
                shown.EndEpisode(1f);
                recording.AddEndEpisode(1f);
                recording.AddTruncation(0f);
                shown.TruncateEpisode(0f);
                Require(recording.Count == 14, "recording count " + recording.Count);
                string path = Path.Combine(Path.GetTempPath(), "verve-mono-" + Guid.NewGuid().ToString("N") + ".vrec");
                recording.Save(path);
                using (var loaded = Recording.Load(path))
                using (var fromBytes = Recording.LoadFromBytes(recording.SaveToBytes()))
                {
                    File.Delete(path);
                    Require(loaded.SaveToBytes().SequenceEqual(fromBytes.SaveToBytes()), "a recording's file and bytes differ");
                    replayed.Teach(0f);
                    replayed.Replay(loaded);
                    replayed.Teach(1f);  // as shown was praised before its trial ended: not part of a recording
                }
                recording.Dispose();
                Require(replayed.ActionProbabilities.Length == 3, "a replayed agent has no policy");
            }
        });

        Check("Agent.UpdateDemonstratedContinuous(Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, Int32, ReadOnlySpan<Single>, ReadOnlySpan<Byte>); " +
              "Recording.AddStepContinuous(Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, Int32, ReadOnlySpan<Single>)", () =>
        {
            var options = new AgentOptions { Actions = 0, ContinuousActions = 2, Seed = 4 }.AddContinuousSensor(false);
            using (var shown = new Agent(options))
            using (var replayed = new Agent(options))
            using (var recording = new Recording(shown))
            {
                for (int i = 0; i < 12; ++i)
                {
                    float[] c = { 0.1f * i - 0.5f };
                    float[] steer = { -c[0], i % 2 == 0 ? 1f : -1f };
                    shown.UpdateDemonstratedContinuous(-0.1f, ReadOnlySpan<int>.Empty, c, 0.1f, 0, steer, ReadOnlySpan<byte>.Empty);
                    recording.AddStepContinuous(-0.1f, ReadOnlySpan<int>.Empty, c, 0.1f, 0, steer);
                    Require(shown.ContinuousAction.SequenceEqual(steer), "the demonstrated values are not played back");
                }
                Expect<VerveException>(() => shown.UpdateDemonstratedContinuous(0f, ReadOnlySpan<int>.Empty, new[] { 0f }, 0.1f, 0,
                                                                                 new[] { 2f, 0f }, ReadOnlySpan<byte>.Empty));
                Expect<VerveException>(() => recording.AddStepContinuous(0f, ReadOnlySpan<int>.Empty, new[] { 0f }, 0.1f, 0, new[] { 0f }));
                using (var loaded = Recording.LoadFromBytes(recording.SaveToBytes())) replayed.Replay(loaded);
                Require(replayed.SaveToBinaryBytes().SequenceEqual(shown.SaveToBinaryBytes()), "a replayed recording trains otherwise");
            }
        });

        Check("ValueAxis.Continuous(Int32, Int32); ValueAxis.Discrete(Int32, Int32); ValueAxis.get_Kind(); ValueAxis.get_Index(); " +
              "ValueAxis.get_Samples(); ValueAxis.Equals(ValueAxis); ValueAxis.Equals(Object); ValueAxis.GetHashCode(); ValueAxis.ToString()", () =>
        {
            ValueAxis c = ValueAxis.Continuous(0, 5), d = ValueAxis.Discrete(0, 2);
            Require(c.Kind == SensorKind.Continuous && c.Index == 0 && c.Samples == 5 && d.Kind == SensorKind.Discrete, "axis fields");
            Require(c.Equals(ValueAxis.Continuous(0, 5)) && !c.Equals((object)d) && c.GetHashCode() == ValueAxis.Continuous(0, 5).GetHashCode(),
                    "axis equality");
            Require(c.ToString().Length > 0, "axis ToString");
            Expect<ArgumentOutOfRangeException>(() => ValueAxis.Continuous(0, 0));
        });

        Check("Agent.SampleValues(ValueAxis, ReadOnlySpan<Int32>, ReadOnlySpan<Single>); " +
              "Agent.SampleValues(ValueAxis, ValueAxis, ReadOnlySpan<Int32>, ReadOnlySpan<Single>); " +
              "Agent.SampleValues(ReadOnlySpan<ValueAxis>, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Span<Single>)", () =>
        {
            float[] one = s_agent.SampleValues(ValueAxis.Continuous(0, 9), new[] { 1 }, new[] { 0f });
            float[] two = s_agent.SampleValues(ValueAxis.Continuous(0, 9), ValueAxis.Discrete(0, 2), new[] { 0 }, new[] { 0f });
            var into = new float[18];
            s_agent.SampleValues(new[] { ValueAxis.Continuous(0, 9), ValueAxis.Discrete(0, 2) }, new[] { 0 }, new[] { 0f }, into);
            Require(one.Length == 9 && two.Length == 18 && into.SequenceEqual(two), "sampled values disagree");
            Require(one.SequenceEqual(two.Skip(9)), "the one-axis sweep at discrete 1 differs from the two-axis sweep's second row");
            Expect<VerveException>(() => s_agent.SampleValues(new[] { ValueAxis.Continuous(0, 9) }, new[] { 0 }, new[] { 0f }, new float[8]));
        });

        Check("Agent.SaveToBytes(); Agent.LoadFromBytes(Byte[]); Agent.LoadFromBytes(ReadOnlySpan<Byte>)", () =>
        {
            s_save = s_agent.SaveToBytes();
            using (Agent fromArray = Agent.LoadFromBytes(s_save))
            using (Agent fromSpan = Agent.LoadFromBytes(new ReadOnlySpan<byte>(s_save)))
            {
                RequireSameActions(fromArray, fromSpan);
            }
            VerveException e = Expect<VerveException>(() => Agent.LoadFromBytes(s_save.Take(s_save.Length / 2).ToArray()));
            Require(e.Code == ResultCode.Format, "a truncated save gave " + e.Code);
        });

        Check("Agent.Save(String); Agent.Load(String)", () =>
        {
            string path = Path.Combine(Path.GetTempPath(), "verve-mono-host-" + Guid.NewGuid().ToString("N") + "-ä.xml");
            try
            {
                s_agent.Save(path);
                using (Agent loaded = Agent.Load(path))
                using (Agent fromBytes = Agent.LoadFromBytes(s_save))
                {
                    RequireSameActions(loaded, fromBytes);
                }
            }
            finally { File.Delete(path); }
            Require(Expect<VerveException>(() => Agent.Load(path)).Code == ResultCode.Io, "a missing file is not an Io error");
        });

        Check("Agent.SaveToBinaryBytes(); Agent.SaveBinary(String)", () =>
        {
            byte[] bytes = s_agent.SaveToBinaryBytes();
            Require(bytes.Length < s_save.Length, "the binary save is not smaller than the XML");
            string path = Path.Combine(Path.GetTempPath(), "verve-mono-host-" + Guid.NewGuid().ToString("N") + ".bin");
            try
            {
                s_agent.SaveBinary(path);
                Require(File.ReadAllBytes(path).SequenceEqual(bytes), "the binary file and bytes differ");
                using (Agent loaded = Agent.Load(path))
                using (Agent fromBytes = Agent.LoadFromBytes(bytes))
                {
                    RequireSameActions(loaded, fromBytes);
                }
            }
            finally { File.Delete(path); }
        });

        Check("VerveException..ctor(ResultCode, String); VerveException.get_Code()", () =>
        {
            var mine = new VerveException(ResultCode.Internal, "message");
            Require(mine.Code == ResultCode.Internal && mine.Message == "message", "VerveException fields");
            // A native failure: the message is read with Marshal.PtrToStringUTF8 on the failing thread.
            VerveException e = Expect<VerveException>(() => new Agent(new AgentOptions { Actions = 0 }));
            Require(e.Code == ResultCode.InvalidArgument && e.Message.StartsWith("VERVE_ERROR_INVALID_ARGUMENT: ", StringComparison.Ordinal) &&
                    e.Message.Contains("verve_agent_create"), "native error message: " + e.Message);
            int steps = (int)s_agent.Stats.Steps;
            Expect<VerveException>(() => s_agent.Update(float.NaN, new[] { 0 }, new[] { 0f }, 0.1f));
            Expect<VerveException>(() => s_agent.Update(0f, null, new[] { 0f }, 0.1f));
            Require(s_agent.Stats.Steps == steps, "a refused update changed the agent");
        });

        Check("Agent.Dispose(); Agent.get_IsDisposed()", () =>
        {
            Require(!s_agent.IsDisposed, "disposed too early");
            s_agent.Dispose();
            s_agent.Dispose();  // twice is harmless
            Require(s_agent.IsDisposed, "IsDisposed after Dispose");
            Expect<ObjectDisposedException>(() => s_agent.Update(0f, new[] { 0 }, new[] { 0f }, 0.1f));
            Expect<ObjectDisposedException>(() => { var unused = s_agent.Stats; });
        });

        // A batch where one body is shown what to do: it answers with the shown action.
        Check("Batch.UpdateDemonstrated(Agent[], ReadOnlySpan<Single>, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, " +
              "ReadOnlySpan<Int32>, Span<Int32>, Span<ResultCode>)", () =>
        {
            var brain = new Brain(new AgentOptions { Actions = 3, Seed = 3 }.AddContinuousSensor());
            Agent[] bodies = { brain.CreateBody(), brain.CreateBody() };
            var batch = new Batch(2);
            var actions = new int[2];
            for (int i = 0; i < 10; ++i)
            {
                batch.UpdateDemonstrated(bodies, new[] { 0f, 0f }, ReadOnlySpan<int>.Empty, new[] { 0.1f * i, -0.1f * i }, 0.1f,
                    new[] { 2, Batch.AgentChooses }, actions);
                Require(actions[0] == 2 && actions[1] >= 0 && actions[1] < 3, "demonstrated batch actions " + actions[0] + "," + actions[1]);
            }
            batch.Dispose();
            foreach (var b in bodies) b.Dispose();
            brain.Dispose();
        });

        // A batch where one agent is shown its continuous action too: it plays the teacher's values back.
        Check("Batch.UpdateDemonstratedContinuous(Agent[], ReadOnlySpan<Single>, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, " +
              "Single, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Span<Int32>, Span<ResultCode>)", () =>
        {
            var options = new AgentOptions { Actions = 0, ContinuousActions = 1, Seed = 3 }.AddContinuousSensor();
            Agent[] agents = { new Agent(options), new Agent(options) };
            var batch = new Batch(2);
            var actions = new int[2];
            for (int i = 0; i < 10; ++i)
            {
                float shown = 0.1f * i - 0.5f;
                batch.UpdateDemonstratedContinuous(agents, new[] { 0f, 0f }, ReadOnlySpan<int>.Empty,
                    new[] { 0.1f * i, -0.1f * i }, 0.1f, new[] { 0, Batch.AgentChooses }, new[] { shown, 9f }, actions);
                Require(agents[0].ContinuousAction[0] == shown, "the shown value played back: " + agents[0].ContinuousAction[0]);
            }
            Expect<VerveException>(() => batch.UpdateDemonstratedContinuous(agents, new[] { 0f, 0f }, ReadOnlySpan<int>.Empty,
                new[] { 0f, 0f }, 0.1f, new[] { 0, Batch.AgentChooses }, new[] { 1.5f, 0f }, actions));
            batch.Dispose();
            foreach (var a in agents) a.Dispose();
        });

        // One brain, two bodies, a batch over both on 2 threads: the same actions as a batch of 1 thread over a
        // twin brain (a brain's bodies act in the batch's phases, docs/crowds.md).
        Check("Brain..ctor(AgentOptions); Brain.CreateBody(); Brain.get_RbfCount(); Batch..ctor(Int32); Batch.get_WorkerCount(); " +
              "Batch.Update(Agent[], ReadOnlySpan<Single>, ReadOnlySpan<Int32>, ReadOnlySpan<Single>, Single, Span<Int32>, Span<ResultCode>); " +
              "Batch.Dispose()", () =>
        {
            var options = new AgentOptions { Actions = 2, Seed = 3 }.AddContinuousSensor();
            Brain solo = new Brain(options), crowd = new Brain(options);
            Agent[] soloBodies = { solo.CreateBody(), solo.CreateBody() };
            Agent[] bodies = { crowd.CreateBody(), crowd.CreateBody() };
            var batch = new Batch(2);
            var one = new Batch(1);
            Require(batch.WorkerCount == 2, "worker count");
            var actions = new int[2];
            var twinActions = new int[2];
            var results = new ResultCode[2];
            for (int step = 0; step < 50; step++)
            {
                float[] sensors = { (float)Math.Sin(step * 0.3), (float)Math.Cos(step * 0.2) };
                float[] rewards = { step % 3 == 0 ? 1f : 0f, 0f };
                one.Update(soloBodies, rewards, new int[0], sensors, 0.1f, twinActions);
                batch.Update(bodies, rewards, new int[0], sensors, 0.1f, actions, results);
                Require(actions[0] == twinActions[0] && actions[1] == twinActions[1], "the batch acted unlike a batch of 1 thread");
            }
            one.Dispose();
            Require(crowd.RbfCount == solo.RbfCount && crowd.RbfCount > 0, "RBF counts differ");
            float[] nan = { float.NaN, 0f };
            var e = Expect<VerveException>(() => batch.Update(bodies, new float[2], new int[0], nan, 0.1f, actions, results));
            Require(e.Code == ResultCode.InvalidArgument && results[0] == ResultCode.InvalidArgument && results[1] == ResultCode.Ok,
                "a bad input was not reported per agent");
            batch.Dispose();
            Expect<ObjectDisposedException>(() => { var unused = batch.WorkerCount; });
            foreach (Agent a in soloBodies.Concat(bodies)) a.Dispose();
            solo.Dispose();
            crowd.Dispose();
        });

        Check("Brain.SaveToBytes(); Brain.SaveToBinaryBytes(); Brain.LoadFromBytes(ReadOnlySpan<Byte>); Brain.Save(String); " +
              "Brain.SaveBinary(String); Brain.Load(String); Brain.Dispose(); Brain.get_IsDisposed()", () =>
        {
            var brain = new Brain(new AgentOptions { Actions = 2 }.AddContinuousSensor());
            Agent body = brain.CreateBody();
            for (int step = 0; step < 20; step++) body.Update(1f, null, new[] { 0.5f }, 0.1f);
            byte[] bytes = brain.SaveToBytes();
            Brain copy = Brain.LoadFromBytes(bytes);
            Require(copy.RbfCount == brain.RbfCount, "a loaded brain has other RBFs");
            string path = Path.Combine(Path.GetTempPath(), "verve-mono-brain-" + Guid.NewGuid().ToString("N") + ".xml");
            brain.Save(path);
            Brain fromFile = Brain.Load(path);
            File.Delete(path);
            Require(fromFile.RbfCount == brain.RbfCount, "a brain loaded from a file has other RBFs");
            byte[] binary = brain.SaveToBinaryBytes();
            Brain binaryCopy = Brain.LoadFromBytes(binary);
            Require(binaryCopy.SaveToBinaryBytes().SequenceEqual(binary), "a binary save loads to another brain");
            string binaryPath = Path.Combine(Path.GetTempPath(), "verve-mono-brain-" + Guid.NewGuid().ToString("N") + ".bin");
            brain.SaveBinary(binaryPath);
            Brain fromBinaryFile = Brain.Load(binaryPath);
            File.Delete(binaryPath);
            Require(fromBinaryFile.SaveToBinaryBytes().SequenceEqual(binary), "a binary file loads to another brain");
            binaryCopy.Dispose();
            fromBinaryFile.Dispose();
            Require(!brain.IsDisposed, "disposed too early");
            brain.Dispose();
            Require(brain.IsDisposed, "IsDisposed after Dispose");
            body.Update(0f, null, new[] { 0.5f }, 0.1f);  // the body keeps the brain alive
            Expect<ObjectDisposedException>(() => brain.CreateBody());
            body.Dispose();
            copy.Dispose();
            fromFile.Dispose();
        });
    }

    const int StepsPerTrial = 20;

    // A short walk on a ring: the discrete sensor says which half, the circular sensor where.
    static void RunTrials(Agent agent, int trials)
    {
        float position = 0f;
        Span<float> continuous = stackalloc float[1];
        Span<int> discrete = stackalloc int[1];
        for (int trial = 0; trial < trials; trial++)
        {
            for (int step = 0; step < StepsPerTrial; step++)
            {
                float reward = position > 0.5f ? 1f : 0f;
                int action = (step & 1) == 0
                    ? agent.Update(reward, new[] { position > 0f ? 1 : 0 }, new[] { position }, 0.1f)
                    : SpanUpdate(agent, reward, discrete, continuous, position);
                Require(action >= 0 && action < 3, "action out of range: " + action);
                position = Math.Max(-1f, Math.Min(1f, position + (action - 1) * 0.1f));
            }
            agent.EndEpisode(position > 0.5f ? 1f : 0f);
        }
    }

    static int SpanUpdate(Agent agent, float reward, Span<int> discrete, Span<float> continuous, float position)
    {
        discrete[0] = position > 0f ? 1 : 0;
        continuous[0] = position;
        return agent.Update(reward, discrete, continuous, 0.1f);
    }

    // Two agents loaded from the same save act alike on the same observations.
    static void RequireSameActions(Agent a, Agent b)
    {
        for (int i = 0; i < 50; i++)
        {
            float x = (float)Math.Sin(i * 0.7);
            int[] d = { i % 2 };
            float[] c = { x };
            Require(a.Update(0.1f, d, c, 0.1f) == b.Update(0.1f, d, c, 0.1f), "loaded agents act differently at step " + i);
        }
    }

    static void Check(string members, Action body)
    {
        try
        {
            body();
            foreach (string m in members.Split(';')) Checked.Add(m.Trim());
            Console.WriteLine("ok    " + members);
        }
        catch (Exception e)
        {
            s_failures++;
            Console.WriteLine("FAIL  " + members + "\n      " + e.ToString().Replace("\n", "\n      "));
        }
    }

    static void Require(bool condition, string what)
    {
        if (!condition) throw new Exception(what);
    }

    static T Expect<T>(Action call) where T : Exception
    {
        try { call(); }
        catch (T e) { return e; }
        throw new Exception("expected " + typeof(T).Name);
    }

    // Every public constructor, method and property accessor of Verve.dll must be named by a Check.
    static void CheckCoverage()
    {
        var members = new HashSet<string>();
        foreach (Type type in typeof(Agent).Assembly.GetExportedTypes().Where(t => !t.IsEnum))
        {
            const BindingFlags flags = BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
            foreach (MethodBase m in type.GetConstructors(flags).Cast<MethodBase>().Concat(type.GetMethods(flags)))
                members.Add(type.Name + "." + m.Name + "(" + string.Join(", ", m.GetParameters().Select(p => TypeName(p.ParameterType))) + ")");
        }
        foreach (string m in members.Except(Checked).OrderBy(m => m))
        {
            s_failures++;
            Console.WriteLine("FAIL  not exercised under Mono: " + m + " (add a Check in MonoHost.cs)");
        }
        foreach (string m in Checked.Except(members).OrderBy(m => m))
        {
            s_failures++;
            Console.WriteLine("FAIL  a Check names no public member: " + m);
        }
        Console.WriteLine("coverage: " + members.Intersect(Checked).Count() + " of " + members.Count + " public members");
    }

    static string TypeName(Type t) =>
        t.IsGenericType
            ? t.Name.Substring(0, t.Name.IndexOf('`')) + "<" + string.Join(", ", t.GetGenericArguments().Select(TypeName)) + ">"
            : t.Name;

    static string RuntimeName()
    {
        Type mono = Type.GetType("Mono.Runtime");
        MethodInfo name = mono == null ? null : mono.GetMethod("GetDisplayName", BindingFlags.NonPublic | BindingFlags.Static);
        return name == null ? "not Mono" : "Mono " + name.Invoke(null, null);
    }
}
