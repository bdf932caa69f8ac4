// Uses the Verve package as a game would and reports where the runtime found libverve.
using System;
using System.IO;
using System.Linq;
using Verve;

var options = new AgentOptions { Actions = 2, Seed = 3 }.AddContinuousSensor();
using var agent = new Agent(options);
int action = 0;
for (int i = 0; i < 20; i++) action = agent.Update(i % 5 == 0 ? 1f : 0f, null, new[] { i / 20f }, 0.1f);
agent.EndEpisode(1f);
using var copy = Agent.LoadFromBytes(agent.SaveToBytes());
Console.WriteLine($"libverve {VerveLibrary.NativeVersion}: {agent.Stats}");

// On Linux the mapped file names the library DllImport("verve") resolved to.
if (File.Exists("/proc/self/maps"))
{
    string? loaded = File.ReadLines("/proc/self/maps")
        .Select(line => line.Split(' ', StringSplitOptions.RemoveEmptyEntries).Last())
        .FirstOrDefault(path => path.EndsWith("/libverve.so", StringComparison.Ordinal));
    Console.WriteLine($"loaded from {loaded}");
}
