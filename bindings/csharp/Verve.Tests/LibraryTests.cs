using Xunit;

namespace Verve.Tests
{
    public class LibraryTests
    {
        [Fact]
        public void LoadedLibraryIsTheVersionTheBindingMirrors()
        {
            Assert.Equal(VerveLibrary.BindingVersionNumber, VerveLibrary.NativeVersionNumber);
            Assert.Equal(VerveLibrary.BindingVersion, VerveLibrary.NativeVersion);
            Assert.True(VerveLibrary.IsCompatible(VerveLibrary.NativeVersionNumber));
        }

        [Fact]
        public void FailuresCarryTheResultNameAndTheNativeMessage()
        {
            var e = Assert.Throws<VerveException>(() => new Agent(new AgentOptions { Actions = 0 }));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            Assert.StartsWith("VERVE_ERROR_INVALID_ARGUMENT: ", e.Message);
            Assert.Contains("verve_agent_create", e.Message);
        }

        [Theory]
        [InlineData(0x000100, true)]   // 0.1.0
        [InlineData(0x000107, true)]   // 0.1.7: patches keep the ABI
        [InlineData(0x000200, false)]  // 0.2.0: 0.x minors may break it
        [InlineData(0x010100, false)]  // 1.1.0
        public void CompatibilityFollowsVersionRules(int nativeVersion, bool compatible) =>
            Assert.Equal(compatible, VerveLibrary.IsCompatible(nativeVersion));
    }
}
