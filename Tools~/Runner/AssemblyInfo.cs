using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("SoftBodyDynamics.Tests.Runner")]
