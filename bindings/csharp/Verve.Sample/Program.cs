// Trains a Verve agent on the 1D signaled hot plate (SignaledHotPlate.cs), prints the learning curve
// and the learned value function, then checks that a saved copy acts like the original.
//   dotnet run --project bindings/csharp/Verve.Sample -p:VerveNativeDir=<dir of libverve.so> -- [trials] [seed]
using System;
using System.Linq;
using Verve;
using Verve.Sample;

int trials = args.Length > 0 ? int.Parse(args[0]) : 150;
int seed = args.Length > 1 ? int.Parse(args[1]) : 1;
const float Dt = 0.1f;
const int Cells = 20, MaxSteps = 500;

Console.WriteLine($"Verve {VerveLibrary.NativeVersion}: 1D signaled hot plate, {Cells} cells, {trials} trials, seed {seed}");

// Thesis settings for this task: policy multiplier 10, continuous resolution 25.
var options = new AgentOptions { Actions = SignaledHotPlate.Actions, PolicyMultiplier = 10f, Resolution = 25, Seed = (ulong)seed }
    .AddDiscreteSensor(SignaledHotPlate.Signals)
    .AddContinuousSensor();
using var agent = new Agent(options);
var task = new SignaledHotPlate(Cells, seed);

// One trial; returns the extra steps taken beyond the shortest path.
int RunTrial(Agent a)
{
    task.Reset();
    int optimal = task.Distance;
    Span<int> discrete = stackalloc int[1];
    Span<float> continuous = stackalloc float[1];
    float reward = 0f; // nothing earned before the first action
    for (int step = 1; step <= MaxSteps; step++)
    {
        discrete[0] = task.Signal;
        continuous[0] = task.Position;
        int action = a.Update(reward, discrete, continuous, Dt);
        (reward, bool done) = task.Act(action);
        if (done)
        {
            a.EndEpisode(reward);
            return step - optimal;
        }
    }
    a.TruncateEpisode(reward); // out of time, not a real end: the plate goes on
    return MaxSteps - optimal;
}

Console.WriteLine("trials      extra steps beyond the shortest path (mean)");
const int Block = 10;
for (int start = 0; start < trials; start += Block)
{
    int count = Math.Min(Block, trials - start);
    double extra = Enumerable.Range(0, count).Select(_ => RunTrial(agent)).Average();
    Console.WriteLine($"{start,4}-{start + count - 1,-4}  {extra,8:F1}  {new string('#', (int)Math.Min(60, Math.Ceiling(extra)))}");
}
Console.WriteLine(agent.Stats);

// V(position) for each signal: it should rise toward the signalled edge.
Console.WriteLine("\nvalue function (left edge -> right edge)");
for (int signal = 0; signal < SignaledHotPlate.Signals; signal++)
{
    float[] values = agent.SampleValues(ValueAxis.Continuous(0, Cells), new[] { signal }, new[] { 0f });
    const string shades = " .:-=+*#%@";
    float lo = values.Min(), hi = values.Max();
    string row = new string(values.Select(v => shades[(int)((v - lo) / Math.Max(hi - lo, 1e-6f) * (shades.Length - 1))]).ToArray());
    Console.WriteLine($"safe {(signal == 0 ? "left " : "right")}  |{row}|  V from {lo:F2} to {hi:F2}");
}

// A save is the whole agent, random stream included: the copy chooses exactly what the original does.
byte[] save = agent.SaveToBytes();
using var copy = Agent.LoadFromBytes(save);
agent.Learning = copy.Learning = false;
var evalA = new SignaledHotPlate(Cells, seed + 1000);
var evalB = new SignaledHotPlate(Cells, seed + 1000);
int mismatches = 0;
double greedyExtra = 0;
for (int t = 0; t < 20; t++)
{
    evalA.Reset();
    evalB.Reset();
    int optimal = evalA.Distance, steps = 0;
    for (bool done = false; !done && steps < MaxSteps; steps++)
    {
        int a = agent.Update(0f, new[] { evalA.Signal }, new[] { evalA.Position }, Dt);
        int b = copy.Update(0f, new[] { evalB.Signal }, new[] { evalB.Position }, Dt);
        if (a != b) mismatches++;
        done = evalA.Act(a).Done;
        evalB.Act(b);
    }
    agent.ResetShortTermMemory();
    copy.ResetShortTermMemory();
    greedyExtra += (steps - optimal) / 20.0;
}
Console.WriteLine($"\nsave: {save.Length} bytes; loaded copy disagreed on {mismatches} actions over 20 test trials");
Console.WriteLine($"learning off, 20 test trials: {greedyExtra:F1} extra steps per trial");
return mismatches == 0 ? 0 : 1;
