// a + b in IEEE binary32, rounded to nearest even, for finite a and b
// (subnormals included): the binning stage's adder (the cell function's
// v - lo, with b's sign flipped by the caller). Overflow gives an infinity
// of the sum's sign; an exact cancellation gives +0. The classic datapath:
// the smaller magnitude aligned with a guard, a round and a sticky bit, one
// add or subtract, a leading-zero normalisation held at the least exponent
// (a subnormal result), and one rounding. Combinational.
module grid_float_add (
    input  wire [31:0] a,
    input  wire [31:0] b,
    output reg  [31:0] sum
);
    // The larger magnitude first (binary32 magnitudes order as their bits).
    wire swap = b[30:0] > a[30:0];
    wire [31:0] greater = swap ? b : a;
    wire [31:0] lesser = swap ? a : b;
    // Effective exponents: a subnormal's is 1, with no hidden bit.
    wire [7:0] greater_exp = greater[30:23] == 0 ? 8'd1 : greater[30:23];
    wire [7:0] lesser_exp = lesser[30:23] == 0 ? 8'd1 : lesser[30:23];
    wire [23:0] greater_mant = {greater[30:23] != 0, greater[22:0]};
    wire [23:0] lesser_mant = {lesser[30:23] != 0, lesser[22:0]};
    wire [7:0] distance = greater_exp - lesser_exp;
    wire [4:0] shift = distance > 8'd27 ? 5'd27 : distance[4:0];
    // The smaller aligned: 24 bits, guard, round, and the sticky OR of the rest.
    wire [53:0] shifted = {lesser_mant, 30'b0} >> shift;
    wire [26:0] aligned = {shifted[53:28], shifted[27] | (|shifted[26:0])};
    wire [27:0] raw = greater[31] != lesser[31] ? {1'b0, greater_mant, 3'b0} - {1'b0, aligned}
                                           : {1'b0, greater_mant, 3'b0} + {1'b0, aligned};

    function automatic [4:0] leading_zeros27(input [26:0] x);
        integer k;
        begin
            leading_zeros27 = 5'd27;
            for (k = 0; k < 27; k = k + 1) if (x[k]) leading_zeros27 = 5'd26 - k[4:0];
        end
    endfunction

    reg [26:0] norm;      // hidden bit at 26 (0 only for a subnormal result)
    reg [8:0] exponent;   // biased, at least 1
    reg [4:0] zeros;
    reg [4:0] left;
    reg [24:0] rounded;
    reg [8:0] final_exp;
    always @* begin
        zeros = leading_zeros27(raw[26:0]);
        if (raw[27]) begin
            norm = {raw[27:2], raw[1] | raw[0]};
            exponent = {1'b0, greater_exp} + 9'd1;
            left = 0;
        end else begin
            // Normalise, but not below the least exponent: a subnormal stays one.
            left = {4'b0, zeros} > {1'b0, greater_exp} - 9'd1 ? greater_exp[4:0] - 5'd1 : zeros;
            norm = raw[26:0] << left;
            exponent = {1'b0, greater_exp} - {4'b0, left};
        end
        rounded = {1'b0, norm[26:3]} + {24'b0, norm[2] & (norm[1] | norm[0] | norm[3])};
        final_exp = rounded[24] ? exponent + 9'd1 : exponent;
        if (raw == 0) sum = 32'b0;
        else if (final_exp >= 9'd255) sum = {greater[31], 8'hFF, 23'b0};
        else if (rounded[24]) sum = {greater[31], final_exp[7:0], 23'b0};
        else sum = {greater[31], rounded[23] ? final_exp[7:0] : 8'd0, rounded[22:0]};
    end
endmodule
