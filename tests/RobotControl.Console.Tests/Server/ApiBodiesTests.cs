using Microsoft.AspNetCore.Http;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary>A body over the server's bound (Kestrel stops reading it with 413) is the API's one-line 400, not a 500.</summary>
public sealed class ApiBodiesTests
{
    [Fact]
    public async Task A_body_over_the_bound_is_one_line_naming_the_request_and_the_bound()
    {
        var context = new DefaultHttpContext();
        context.Request.Body = new OverLimitStream();

        var (body, problem) = await ApiBodies.Read<ValueBody>(context.Request, "kp");

        Assert.Null(body);
        Assert.Equal("kp: the body is over 4 MiB", problem);
    }

    /// <summary>What Kestrel's body reader does past <c>MaxRequestBodySize</c>.</summary>
    private sealed class OverLimitStream : MemoryStream
    {
        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) =>
            throw new BadHttpRequestException("Request body too large.", StatusCodes.Status413PayloadTooLarge);

        public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken) =>
            throw new BadHttpRequestException("Request body too large.", StatusCodes.Status413PayloadTooLarge);
    }
}
