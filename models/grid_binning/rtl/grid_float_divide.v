// a / b in IEEE binary32, rounded to nearest even, for positive finite a and
// b (subnormals included): the setup's divider, which gives each axis its
// scale, dims / extent, or 1 / cell_size (GridBounds::geometry). Overflow
// gives +infinity (a subnormal extent), a quotient below the normal range a
// subnormal. Both operands normalised, a 27-bit quotient of their mantissas
// with a guard bit and the remainder as sticky, one rounding. Combinational:
// the setup spends one slot on each axis.
module grid_float_divide (
    input  wire [31:0] a,
    input  wire [31:0] b,
    output reg  [31:0] quotient
);
    function automatic [4:0] leading_zeros24(input [23:0] x);
        integer k;
        begin
            leading_zeros24 = 5'd24;
            for (k = 0; k < 24; k = k + 1) if (x[k]) leading_zeros24 = 5'd23 - k[4:0];
        end
    endfunction
    // Mantissas with the leading one at bit 23; exponents biased, below 1 for a subnormal.
    wire [23:0] a_raw = {a[30:23] != 0, a[22:0]};
    wire [23:0] b_raw = {b[30:23] != 0, b[22:0]};
    wire [4:0] a_zeros = leading_zeros24(a_raw);
    wire [4:0] b_zeros = leading_zeros24(b_raw);
    wire [23:0] a_mant = a_raw << a_zeros;
    wire [23:0] b_mant = b_raw << b_zeros;
    wire signed [10:0] a_exp = $signed({3'b0, a[30:23] == 0 ? 8'd1 : a[30:23]}) - $signed({6'b0, a_zeros});
    wire signed [10:0] b_exp = $signed({3'b0, b[30:23] == 0 ? 8'd1 : b[30:23]}) - $signed({6'b0, b_zeros});
    // a_mant / b_mant lies in (1/2, 2): 26 or 27 quotient bits, by restoring
    // division (27 subtractions of 25 bits), the remainder left for the sticky bit.
    reg [26:0] whole;
    reg [25:0] rest;
    integer i;
    always @* begin
        rest = {2'b0, a_mant};
        for (i = 26; i >= 0; i = i - 1) begin
            whole[i] = rest >= {2'b0, b_mant};
            if (whole[i]) rest = rest - {2'b0, b_mant};
            if (i > 0) rest = rest << 1;
        end
    end

    reg [23:0] mant;          // the quotient's 24 leading bits
    reg guard, sticky;
    reg signed [10:0] exponent;
    reg [10:0] shift;         // right shift into the subnormal range
    reg [49:0] wide;  // the subnormal shift: 24 bits, guard and 25 spare
    reg [24:0] rounded;
    always @* begin
        wide = 0;
        shift = 0;
        if (whole[26]) begin
            mant = whole[26:3];
            guard = whole[2];
            sticky = (|whole[1:0]) | (rest != 0);
            exponent = a_exp - b_exp + 11'sd127;
        end else begin
            mant = whole[25:2];
            guard = whole[1];
            sticky = whole[0] | (rest != 0);
            exponent = a_exp - b_exp + 11'sd126;
        end
        if (exponent < 11'sd1) begin
            // Subnormal: 1 - exponent more bits fall into the guard and sticky.
            shift = 11'd1 - exponent;
            // 25 spare bits below the guard: nothing is shifted out under 26.
            wide = shift > 11'd25 ? {49'b0, (|mant) | guard} : {mant, guard, 25'b0} >> shift[4:0];
            mant = wide[49:26];
            guard = wide[25];
            sticky = sticky | (|wide[24:0]);
        end
        rounded = {1'b0, mant} + {24'b0, guard & (sticky | mant[0])};
        if (exponent >= 11'sd1) begin
            if (rounded[24]) begin
                quotient = exponent + 11'sd1 >= 11'sd255 ? 32'h7F80_0000 : {1'b0, exponent[7:0] + 8'd1, 23'b0};
            end else begin
                quotient = exponent >= 11'sd255 ? 32'h7F80_0000 : {1'b0, exponent[7:0], rounded[22:0]};
            end
        end else begin
            quotient = {1'b0, rounded[23] ? 8'd1 : 8'd0, rounded[22:0]};  // a carry into 2^-126 is normal
        end
    end
endmodule
